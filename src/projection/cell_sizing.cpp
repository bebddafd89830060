// Cell sizes against the target edge length (cell_sizing.hpp).
#include "projection/cell_sizing.hpp"

#include <isopatch/level_set_curvature.hpp>

#include <algorithm>
#include <limits>

namespace isopatch {
namespace {

/// A cell must stay at least this many target edge lengths long to be split for its curvature.
constexpr double kMinCurvedCellEdges = 3.0;

}  // namespace

std::function<double(const Vec3&)> size_function(const Surface& surface, const TargetSizes& spec) {
  if (!spec.varies()) return [edge = spec.largest](const Vec3&) { return edge; };
  return [&surface, spec](const Vec3& p) { return target_size(surface, spec, p); };
}

std::vector<std::size_t> cells_too_large_for(const CellPartition& partition,
                                             const std::function<double(const Vec3&)>& size_at,
                                             int max_level) {
  std::vector<std::size_t> cells;
  for (std::size_t c = 0; c < partition.cells.size(); ++c) {
    const PartitionCell& cell = partition.cells[c];
    if (cell.level >= max_level) continue;
    double h = std::numeric_limits<double>::infinity();
    for (const CellLoop& loop : cell.loops)
      for (std::uint32_t k : loop.corners) h = std::min(h, size_at(partition.corners[k].position));
    if (cell.bounds.size().maxCoeff() > kAutoSegments * h) cells.push_back(c);
  }
  return cells;
}

bool starting_cells_too_curved(const CellPartition& partition, const Surface& surface, int level,
                               double max_turn, const std::function<double(const Vec3&)>& size_at) {
  // A corner is shared by up to four cells: its curvature and size are evaluated once (-1: not yet).
  std::vector<double> kappa(partition.corners.size(), -1.0), h(partition.corners.size(), -1.0);
  std::size_t curved = 0, corners = 0;
  for (const PartitionCell& cell : partition.cells) {
    if (cell.level != level) continue;
    const double size = cell.bounds.size().maxCoeff();
    for (const CellLoop& loop : cell.loops)
      for (std::uint32_t c : loop.corners) {
        const Vec3& p = partition.corners[c].position;
        if (kappa[c] < 0.0) kappa[c] = max_abs_principal_curvature(surface, p), h[c] = size_at(p);
        ++corners;
        // Infinite curvature (a singular point) counts as curved; NaN compares false.
        if (size * kappa[c] > max_turn && size > kMinCurvedCellEdges * h[c]) ++curved;
      }
  }
  return 2 * curved > corners;
}

}  // namespace isopatch
