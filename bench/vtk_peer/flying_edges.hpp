#pragma once
/// \file flying_edges.hpp
/// The VTK peer of the performance report: f sampled on a regular grid with isopatch's batch
/// evaluation, then VTK's Flying Edges (vtkFlyingEdges3D) extracts f = 0. Benchmark code only: the
/// isopatch library never depends on VTK.

#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <array>
#include <cstddef>
#include <string>

namespace isopatch::bench {

struct FlyingEdgesOptions {
  int grid = 64;  ///< cells along the longest side of the box; the cells are cubes
  /// threads of the sampling and of VTK's SMP back end (set through VTK_SMP_MAX_THREADS, so it
  /// holds for the first call in a process)
  int threads = 1;
};

/// What Flying Edges produced and where its time went (wall times, seconds).
struct FlyingEdgesResult {
  Mesh mesh;                           ///< triangles counter-clockwise seen from outside (along grad f)
  std::array<int, 3> samples{};        ///< grid points per axis
  std::size_t value_evaluations = 0;   ///< evaluations of f (one per grid point)
  std::size_t non_finite_values = 0;   ///< of those, NaN or infinite (taken as positive)
  std::size_t degenerate_dropped = 0;  ///< triangles with a repeated vertex, dropped
  double sample_seconds = 0.0;         ///< evaluating f on the grid
  double contour_seconds = 0.0;        ///< vtkFlyingEdges3D
  double convert_seconds = 0.0;        ///< VTK's polygons to an isopatch Mesh
  double seconds = 0.0;                ///< the sum: grid in, Mesh out
  std::string smp_backend;             ///< VTK's SMP back end (TBB, STDThread, Sequential)
};

/// Samples f at the grid points of `box` (cubic cells, options.grid along the longest side, the
/// grid anchored at box.lo and reaching at least box.hi) and runs Flying Edges at f = 0.
/// \throw InputError for an invalid box, grid < 2 or threads < 1; whatever evaluating f throws
FlyingEdgesResult flying_edges(const Surface& surface, const Box& box, const FlyingEdgesOptions& options);

}  // namespace isopatch::bench
