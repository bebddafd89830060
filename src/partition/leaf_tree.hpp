#pragma once
/// \file leaf_tree.hpp
/// The leaves of an adaptive octree below a set of root cells at one depth (docs/algorithms.md 2.12.1): a map
/// from cells to "leaf" or "split", point location, splitting and 2:1 balance across faces and edges.
/// Cells outside every root are "outside" (empty space for the partition).

#include "partition/partition.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace isopatch {

struct CellKeyHash {
  std::size_t operator()(const CellKey& key) const;
};

class LeafTree {
 public:
  /// \pre 0 <= min_depth <= max_depth <= Lattice::kMaxDepth
  LeafTree(int min_depth, int max_depth) : min_depth_(min_depth), max_depth_(max_depth) {}

  /// Adds the root cell `coords` at min_depth as a leaf; false when it is outside the root cube or
  /// already covered.
  bool add_root(const LatticePoint& coords);

  enum class Where : std::uint8_t { Outside, Leaf, Split };
  struct Found {
    Where where = Where::Outside;
    int depth = -1;  ///< for Leaf: depth of the leaf covering the cell (<= the cell's depth)
  };
  /// What covers the cell (depth, coords): a leaf at its depth or coarser, finer leaves (Split), or
  /// nothing (Outside, also for coordinates outside the root cube).
  Found locate(int depth, const LatticePoint& coords) const;

  /// Whether the cell at `depth` with coordinates `coords` + `offset` is subdivided into finer leaves.
  bool neighbour_split(const CellKey& cell, const std::array<int, 3>& offset) const;

  /// Replaces the leaf by its 8 children. \pre `leaf` is a leaf with depth < max_depth.
  void split(const CellKey& leaf);

  /// Splits leaves until every leaf's face and edge neighbours (same-size cells sharing a face or an
  /// edge, when covered) are covered by leaves at most one level coarser. Returns the cells split, in
  /// the order they were split. Splits only make cells finer, so after a balance only leaves made since
  /// (children of splits) can break the rule; those alone are checked, unless a root was added (a new
  /// coarse neighbour of old leaves), when every leaf is. The tree is the same either way: the coarsest
  /// balanced refinement of what it was.
  std::vector<CellKey> balance();

  /// All leaves, sorted by (depth, coords).
  std::vector<CellKey> leaves() const;

  int min_depth() const { return min_depth_; }
  int max_depth() const { return max_depth_; }

 private:
  int min_depth_;
  int max_depth_;
  std::unordered_map<CellKey, bool, CellKeyHash> nodes_;  // true: leaf, false: split
  std::vector<CellKey> fresh_;                            // leaves made by split() since the last balance()
  bool rooted_ = true;                                    // a root was added since the last balance()
};

/// The 18 offsets of the face (6) and edge (12) neighbours of a cell.
const std::array<std::array<int, 3>, 18>& face_edge_offsets();

}  // namespace isopatch
