#pragma once
/// \file octree_descent.hpp
/// The descent shared by both octree builders (docs/algorithms.md 2.4, 2.11): from the root cube down
/// to surface_depth, skipping cells that cannot hold the surface, then closing the holes that a wrong
/// heuristic prune left. The uniform builder classifies the cells it yields; the adaptive builder
/// takes them as the roots of its tree. One sample cache serves the descent and the builder after it.

#include <isopatch/surface.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include "partition/cell.hpp"
#include "partition/partition.hpp"
#include "partition/sample_cache.hpp"

namespace isopatch {

/// A cell at surface_depth that may hold the surface, with its corner values.
struct SurfaceCell {
  Cell cell;
  std::array<double, 8> values{};  ///< f at the corners (cube numbering)
  std::uint8_t negative = 0;       ///< bit i set when corner i is negative
};

/// The cells at settings.surface_depth inside the lattice's clip box whose corners change sign, or
/// whose edge samples do (equal corner signs: a feature smaller than the cell), in descent order.
///
/// A cell is skipped as empty when bound() excludes 0 (sound) or, when the surface gives no bound, when
/// all 8 corners and the centre share a sign and |f(centre)| > 2 L half-diagonal, with L the largest
/// |grad f| at those 9 points (a first-order Taylor bound with a safety factor 2; the centre's gradient
/// alone fails at critical points such as the tanglecube's origin). Afterwards the cells around every
/// edge whose end signs differ are visited too, so every crossed edge is surrounded by cells.
/// Fills the descent counters of `stats` (cells visited, pruned, empty, recovered, intervals).
/// \throw EvaluationError when f is not finite at a sample; LimitError when settings.cancel is raised.
std::vector<SurfaceCell> descend_to_surface_cells(const Surface& surface, const Lattice& lattice,
                                                  const PartitionSettings& settings, SampleCache& cache,
                                                  PartitionStats& stats);

/// The edge test on the 12 edges of `cell` (docs/algorithms.md 2.9.1): an edge whose end signs differ changes
/// sign exactly once along its samples, any other edge never. With settings.use_intervals, an axis on
/// which gradient_bound proves f monotone passes without samples. Counts in `stats`.
bool cell_edges_pass(const Surface& surface, const Lattice& lattice, const PartitionSettings& settings,
                     SampleCache& cache, const Cell& cell, const std::array<double, 8>& values,
                     PartitionStats& stats);

/// The raise of LimitError("cancelled") when settings.cancel is set and true.
void check_partition_cancel(const PartitionSettings& settings);

}  // namespace isopatch
