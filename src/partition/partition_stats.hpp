#pragma once
/// \file partition_stats.hpp
/// What building a partition did: cells visited and pruned, verdicts, loops, evaluations of f.

#include <array>
#include <cstdint>

namespace isopatch {

/// The deepest level any partition refines to (the octree's finest lattice depth).
inline constexpr int kMaxPartitionLevel = 20;

/// The number of values of ComplexReason (cell_partition.hpp), for counts per reason.
inline constexpr int kComplexReasonCount = 7;

struct PartitionStats {
  std::uint64_t cells_visited = 0;
  std::uint64_t pruned_by_interval = 0;   ///< cells skipped because bound() excludes 0 (sound)
  std::uint64_t pruned_by_heuristic = 0;  ///< cells skipped by the first-order empty test (heuristic)
  std::uint64_t empty_surface_cells = 0;  ///< cells at surface depth with equal signs everywhere sampled
  std::uint64_t cells_recovered = 0;      ///< leaves found next to crossings after a wrong heuristic prune
  std::uint64_t simple_leaves = 0;
  std::uint64_t complex_leaves = 0;
  std::array<std::uint64_t, kComplexReasonCount> complex_by_reason{};  ///< indexed by ComplexReason
  std::uint64_t leaves_without_loops = 0;  ///< Complex: equal corner signs, an edge sample of the other sign
  std::uint64_t loops = 0;
  std::uint64_t orientation_disagreements = 0;    ///< loops of any leaf whose Newell normal opposes grad f
  std::uint64_t edges_certified_by_interval = 0;  ///< edge tests settled by gradient_bound
  std::uint64_t value_evaluations = 0;            ///< all evaluations of f alone, including the two below
  std::uint64_t segment_sample_evaluations = 0;   ///< of which for the edge test
  std::uint64_t root_evaluations = 0;             ///< of which inside the root finder
  std::uint64_t gradient_evaluations = 0;         ///< evaluations of f with its gradient
  std::uint64_t interval_evaluations = 0;         ///< calls of bound() and gradient_bound()
  // Filled in adaptive mode only (the descent counters above then come from the descent to the
  // root cells).
  std::array<std::uint64_t, kMaxPartitionLevel + 1> leaves_per_depth{};  ///< output leaves by depth
  std::uint64_t leaves_with_flat_corners = 0;  ///< leaves with a corner inside one of their faces
  std::uint64_t max_loop_size = 0;             ///< most corners of any loop
  std::uint64_t adaptive_rounds = 0;           ///< analyse / split rounds until stable
  std::uint64_t forced_splits = 0;             ///< leaves split because of force_split
  std::uint64_t topology_splits = 0;           ///< leaves split because their topology was in doubt
  std::uint64_t balance_splits = 0;            ///< leaves split to restore 2:1 balance
};

}  // namespace isopatch
