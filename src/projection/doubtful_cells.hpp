#pragma once
/// \file doubtful_cells.hpp
/// The cells whose topology a partition leaves in doubt after refining them to its limit, and whether
/// that doubt concerns the mesh's topology (for the warning that the mesh may join sheets).

#include <array>
#include <cstddef>

#include "partition/cell_partition.hpp"

namespace isopatch {

/// Whether only a finer partition helps this cell: two loops, an ambiguous face, an edge crossed twice,
/// a loop against the gradients, or no loop. The other single-sheet tests (face, normal cone) are
/// sufficient conditions; a cell failing only those still gets its patch and the acceptance tests decide.
bool needs_refinement(const PartitionCell& cell);

struct DoubtfulCells {
  std::size_t count = 0;
  double largest_side = 0.0;  ///< of the largest doubtful cell (0 without any)
  std::array<std::size_t, kComplexReasonCount> by_reason{};
  /// Doubtful cells that put the topology in question: two loops or an ambiguous face always, edges
  /// crossed twice when they are more than 1% of the cells (a few are mostly edges grazing the surface,
  /// which the fans close correctly); not the ambiguous faces that the surface only grazes.
  std::size_t topology = 0;
  /// Cells whose ambiguous faces the surface only grazes (Partitioner::only_grazes_ambiguous_faces).
  std::size_t grazing_faces = 0;
};

/// The cells of `partition` (the last build of `partitioner`) that still need refinement.
/// Evaluates f through `f` for cells with ambiguous faces only.
DoubtfulCells doubtful_cells(const CellPartition& partition, const Partitioner& partitioner,
                             const Sampler& f);

}  // namespace isopatch
