// Cells still in doubt after refinement (doubtful_cells.hpp).
#include "projection/doubtful_cells.hpp"

#include <algorithm>

namespace isopatch {
namespace {

/// An edge crossed twice in a few cells is mostly an edge grazing the surface, which the fans close
/// correctly; in more than this share of the cells, sheets closer than a cell are the likelier cause.
constexpr double kDoubtfulEdgeShare = 0.01;

}  // namespace

bool needs_refinement(const PartitionCell& cell) {
  if (cell.loops.size() != 1) return true;
  switch (cell.reason) {
    case ComplexReason::None:
    case ComplexReason::FaceTest:
    case ComplexReason::NormalCone:
      return false;
    case ComplexReason::SeveralLoops:
    case ComplexReason::AmbiguousFace:
    case ComplexReason::EdgeTest:
    case ComplexReason::Orientation:
      return true;
  }
  return true;
}

DoubtfulCells doubtful_cells(const CellPartition& partition, const Partitioner& partitioner,
                             const Sampler& f) {
  DoubtfulCells doubtful;
  for (std::size_t c = 0; c < partition.cells.size(); ++c) {
    const PartitionCell& cell = partition.cells[c];
    if (!needs_refinement(cell)) continue;
    ++doubtful.count;
    ++doubtful.by_reason[static_cast<std::size_t>(cell.reason)];
    doubtful.largest_side = std::max(doubtful.largest_side, cell.bounds.size().maxCoeff());
    if (cell.reason == ComplexReason::AmbiguousFace && partitioner.only_grazes_ambiguous_faces(c, f))
      ++doubtful.grazing_faces;
  }
  const auto reason = [&](ComplexReason r) { return doubtful.by_reason[static_cast<std::size_t>(r)]; };
  doubtful.topology =
      reason(ComplexReason::SeveralLoops) + reason(ComplexReason::AmbiguousFace) - doubtful.grazing_faces;
  if (static_cast<double>(reason(ComplexReason::EdgeTest)) >
      kDoubtfulEdgeShare * static_cast<double>(partition.cells.size()))
    doubtful.topology += reason(ComplexReason::EdgeTest);
  return doubtful;
}

}  // namespace isopatch
