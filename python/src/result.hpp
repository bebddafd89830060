#pragma once
// What isopatch.mesh() and mesh_volume() return to Python before the pure-Python Mesh wraps it: the
// library's mesh, the surface it was meshed on, statistics, unit normals and, for a Python function,
// the distances to f = 0 itself.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace isopatch::python {

struct MeshResult {
  Mesh mesh;
  SurfacePtr surface;  ///< the surface meshed (a Python function's: the interpolant of its samples)
  MeshStats stats;
  std::vector<Vec3> normals;                    ///< unit grad f at each vertex
  std::optional<std::vector<double>> distance;  ///< f / |grad f| of a Python function, else from `surface`
  std::map<std::string, double> extra;          ///< statistics of the Python side (calls, samples, ...)

  /// Fills `normals` from surface's gradient at every vertex.
  void normals_from_surface();
  /// Runs the exact self-intersection check (self_intersection.hpp) on the mesh the library returned and
  /// records its pairs in stats.warnings, as the command line does: no mesh comes back crossing itself
  /// without saying so.
  void check_crossings();
};

/// Binds MeshResult as isopatch._isopatch.MeshResult (arrays, fields, stats, write, analyze, render).
void bind_result(pybind11::module_& m);

}  // namespace isopatch::python
