#pragma once
/// \file isotropic_remesh.hpp
/// The remeshing peer of the performance report: CGAL's Polygon_mesh_processing::isotropic_remeshing
/// applied to a mesh (Flying Edges' in the report). Benchmark code only: the isopatch library never
/// depends on CGAL.

#include <isopatch/mesh.hpp>

namespace isopatch::bench {

struct RemeshOptions {
  double target_edge = 0.0;  ///< target edge length; <= 0: from target_vertices
  /// When target_edge <= 0: the length whose equilateral triangles tile the input's area with this
  /// many vertices (area per vertex sqrt(3)/2 L^2); <= 0 as well: the input's mean edge length.
  double target_vertices = 0.0;
  int iterations = 5;  ///< rounds of split, collapse, flip, tangential relaxation and projection
};

struct RemeshResult {
  Mesh mesh;                 ///< orientation kept from the input
  double target_edge = 0.0;  ///< the length used
  double seconds = 0.0;      ///< wall time: building CGAL's mesh, remeshing, extraction
};

/// Remeshes `input` with isotropic_remeshing (CGAL's defaults otherwise: no protected edges, one
/// relaxation step per round, every vertex projected back onto the input mesh, not onto f = 0).
/// \throw InputError when the input is empty, not a polygon mesh CGAL can build (non-manifold), or
///        options are not positive where they must be
RemeshResult isotropic_remesh(const Mesh& input, const RemeshOptions& options);

}  // namespace isopatch::bench
