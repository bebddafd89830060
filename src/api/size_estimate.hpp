#pragma once
// The output's size and the surface's largest curvature, estimated before any meshing from a coarse
// Marching Cubes mesh: a request beyond the vertex budget is refused at once with the estimate in the
// message rather than after minutes of work, and the multiresolution driver chooses its first level
// without meshing a base it would throw away.

#include <isopatch/geometry.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <cstdint>

namespace isopatch {

/// Cells of the coarse Marching Cubes grid along the longest box side that measures the area.
inline constexpr int kEstimateGrid = 32;

/// How close to f = 0 (|f| / |grad f|, over the grid's cell) a grid-mesh vertex is put before its
/// curvature is measured.
inline constexpr double kEstimateTolerance = 1e-6;

/// What the coarse grid tells about the mesh to come.
struct SizeEstimate {
  /// About how many vertices a mesh at the target edge length h has: a triangulation of area A by
  /// equilateral triangles of side h has 2 A / (sqrt(3) h^2) vertices. Features smaller than the grid's
  /// cells are missed, and sizes below h make the real count larger: a lower bound in practice.
  double vertices = 0.0;
  /// The largest |principal curvature| of f = 0 at the grid mesh's vertices moved onto it
  /// (project_to_surface; points where it is not finite, at singular points, skipped); 0 when not asked for.
  /// The grid misses features smaller than its cells, so this is a first guess that the multiresolution
  /// driver checks on its base.
  double largest_curvature = 0.0;
  std::uint64_t value_evaluations = 0;
  std::uint64_t gradient_evaluations = 0;  // the projections' and the curvature samples' (second order)
  /// False when f changes sign at no grid edge (a surface thinner than a cell, or none): then nothing is
  /// estimated (vertices and curvature 0) and the mesher, which looks deeper, decides.
  bool found = true;
};

/// Estimates the mesh of `surface` in `box` with `settings`' target edge length, from a Marching Cubes
/// mesh of a kEstimateGrid grid (about kEstimateGrid^3 evaluations of f, a few milliseconds), with the
/// largest curvature when `with_curvature` (per grid-mesh vertex, a few evaluations of f and grad f and
/// one second-order evaluation).
/// \throw EvaluationError when f is not finite at a grid point; LimitError("cancel") when cancelled.
SizeEstimate estimate_size(const Surface& surface, const Settings& settings, const Box& box,
                           bool with_curvature);

/// Throws LimitError("max_vertices") naming the estimate when settings.max_vertices is set (not 0) and
/// the estimate exceeds it.
void check_estimated_size(const SizeEstimate& estimate, const Settings& settings, const Box& box);

}  // namespace isopatch
