#pragma once
// Python functions f(points) -> values as surfaces, called in batches: the library evaluates a surface
// point by point from its meshing threads, which a Python function could serve only one point per call
// and one thread at a time. Instead f is sampled on a grid in a few large calls, the grid's tricubic
// B-spline interpolant (volume_surface.hpp) is meshed without the GIL, and the vertices are then moved
// onto f = 0 itself by batched Newton steps (one call per step for all vertices still moving).

#include <pybind11/pybind11.h>
#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/volume.hpp>

#include <cstddef>
#include <vector>

namespace isopatch::python {

/// f given as Python callables. `value` takes an (N, 3) float64 array and returns N values;
/// `gradient`, when not None, returns an (N, 3) array of gradients. Calls need the GIL.
struct BatchFunction {
  pybind11::object value;
  pybind11::object gradient;  ///< None: central differences (see evaluate)
  std::size_t batch = 1 << 18;
  std::size_t calls = 0;   ///< calls made into Python so far
  std::size_t points = 0;  ///< points passed in those calls

  /// f at every point, in calls of at most `batch` points.
  /// \throw EvaluationError for a value that is NaN or infinite (naming the point), InputError for a
  ///        result of the wrong shape; a Python exception raised by f propagates unchanged.
  std::vector<double> values(const std::vector<Vec3>& points);
  /// f and grad f at every point: the gradient callable, or central differences of step `h` in the
  /// same batched call as the values (6 extra points per point).
  void values_gradients(const std::vector<Vec3>& points, double h, std::vector<double>& f,
                        std::vector<Vec3>& g);
};

/// f sampled on a grid over `box` with about `cells` cells along its longest side (at least 3 along
/// every side), as a Volume (spacing per axis fits the box exactly).
Volume sample_on_grid(BatchFunction& f, const Box& box, int cells);

/// What project_vertices did.
struct ProjectionOutcome {
  std::size_t unprojected = 0;  ///< vertices left where the interpolant put them (no convergence)
  int steps = 0;                ///< Newton steps taken
};

/// Moves the vertices of `mesh` onto f = 0 by Newton steps p -= f grad f / |grad f|^2, at most 8,
/// all vertices still moving in one batched call per step; a vertex on a face of `box` moves within
/// that face. A step longer than `max_step` is not taken (the vertex stays: the interpolant's surface
/// is then the better answer). Fills `normals` with the unit gradients and `distance` with
/// f / |grad f| at the final positions.
ProjectionOutcome project_vertices(BatchFunction& f, Mesh& mesh, const Box& box, double max_step,
                                   std::vector<Vec3>& normals, std::vector<double>& distance);

}  // namespace isopatch::python
