#pragma once
/// \file cell_sizing.hpp
/// How the projection mesher judges a partition's cell sizes against the target edge length: cells
/// too long for the local size (a size field), and starting cells too long for the curvature (patches
/// that would wrap around a tube).

#include <isopatch/surface.hpp>

#include <cstddef>
#include <functional>
#include <vector>

#include "partition/cell_partition.hpp"
#include "surface/target_size.hpp"

namespace isopatch {

/// Automatic resolution aims at this many segments per side (cells of 4..8 edge lengths).
inline constexpr double kAutoSegments = 8.0;

/// The target edge length at a point (target_size.hpp): constant unless max_error or a size field is
/// set. `surface` must outlive the result.
std::function<double(const Vec3&)> size_function(const Surface& surface, const TargetSizes& spec);

/// Cells shallower than `max_level` whose cell is longer than kAutoSegments times the smallest target
/// size at their corners, ascending.
std::vector<std::size_t> cells_too_large_for(const CellPartition& partition,
                                             const std::function<double(const Vec3&)>& size_at,
                                             int max_level);

/// Whether the surface is curved at the scale of the starting cells (Settings::max_cell_curvature):
/// more than half of the corners of the cells at `level` sit in a cell longer than `max_turn` radii of
/// the largest principal curvature at the corner and longer than 3 target sizes. A median, not a
/// per-cell rule: splitting single cells adds level transitions, whose seams cost more than the strain
/// they remove (measured in docs/whole-surface-quality.md).
bool starting_cells_too_curved(const CellPartition& partition, const Surface& surface, int level,
                               double max_turn, const std::function<double(const Vec3&)>& size_at);

}  // namespace isopatch
