#pragma once
/// \file vertex_target.hpp
/// The grid resolution of Dual Contouring (dual_contouring.hpp; Ju, Losasso, Schaefer & Warren,
/// "Dual contouring of Hermite data", SIGGRAPH 2002) for a given vertex count, so that its meshes can
/// be compared with others of the same size. A mesh of a surface on a grid of N cells per side has
/// about c N^2 vertices: a first run at a small N estimates c, then a few corrections. Benchmark code.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>

#include "dual_contouring.hpp"

namespace isopatch::bench {

/// The largest options.cells the search tries.
inline constexpr int kMaxSearchCells = 1024;

/// Dual Contouring of `surface` in `box` at the options.cells (in [2, kMaxSearchCells]) whose vertex
/// count comes closest to `vertices` among the few the search runs (options.cells itself is ignored).
/// The result's search_runs and search_seconds cover the whole search.
/// \throw InputError for vertices == 0, or when no run up to kMaxSearchCells finds the surface;
///        whatever dual_contouring throws
DualContouringResult dual_contouring_for_vertices(const Surface& surface, const Box& box,
                                                  std::size_t vertices, DualContouringOptions options);

}  // namespace isopatch::bench
