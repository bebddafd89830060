// Adaptive octree bookkeeping: the tree is a hash map of cells; locating a cell looks up its ancestors
// from its own depth upwards, at most 21 lookups.
#include "partition/leaf_tree.hpp"

#include "core/cube_numbering.hpp"
#include "partition/index_map.hpp"

#include <algorithm>
#include <deque>

namespace isopatch {

namespace {

bool in_root(int depth, const LatticePoint& c) {
  const std::uint64_t cells = std::uint64_t{1} << depth;
  return c[0] < cells && c[1] < cells && c[2] < cells;
}

LatticePoint ancestor(const LatticePoint& c, int levels) {
  return {c[0] >> levels, c[1] >> levels, c[2] >> levels};
}

}  // namespace

std::size_t CellKeyHash::operator()(const CellKey& key) const {
  return static_cast<std::size_t>(mix64(half_key(key.coords) * 32 + static_cast<std::uint64_t>(key.depth)));
}

const std::array<std::array<int, 3>, 18>& face_edge_offsets() {
  static const std::array<std::array<int, 3>, 18> offsets = [] {
    std::array<std::array<int, 3>, 18> o{};
    std::size_t n = 0;
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          const int nonzero = (x != 0) + (y != 0) + (z != 0);
          if (nonzero == 1 || nonzero == 2) o[n++] = {x, y, z};
        }
    return o;
  }();
  return offsets;
}

bool LeafTree::add_root(const LatticePoint& coords) {
  if (!in_root(min_depth_, coords) || locate(min_depth_, coords).where != Where::Outside) return false;
  nodes_.emplace(CellKey{min_depth_, coords}, true);
  rooted_ = true;
  return true;
}

LeafTree::Found LeafTree::locate(int depth, const LatticePoint& coords) const {
  if (depth < min_depth_ || !in_root(depth, coords)) return {};
  // A node exists exactly when its parent is split, so the deepest node on the path from the root
  // decides: a leaf covers the cell, a split node at the cell's own depth has finer leaves, and no node
  // at all means outside. Searched from the cell's depth upwards: neighbours are mostly of about its
  // size, so this is one or two lookups where the walk from the root took one per level.
  for (int d = depth; d >= min_depth_; --d) {
    const auto it = nodes_.find(CellKey{d, ancestor(coords, depth - d)});
    if (it == nodes_.end()) continue;
    if (it->second) return {Where::Leaf, d};
    return d == depth ? Found{Where::Split, -1} : Found{};
  }
  return {};
}

bool LeafTree::neighbour_split(const CellKey& cell, const std::array<int, 3>& offset) const {
  LatticePoint n = cell.coords;
  for (int a = 0; a < 3; ++a) n[a] += static_cast<std::uint32_t>(offset[a]);  // wraps: then outside
  return locate(cell.depth, n).where == Where::Split;
}

void LeafTree::split(const CellKey& leaf) {
  const auto it = nodes_.find(leaf);
  if (it == nodes_.end() || !it->second || leaf.depth >= max_depth_) return;  // precondition violated
  nodes_[leaf] = false;
  for (const auto& o : cube::kCorner) {
    const CellKey child{leaf.depth + 1,
                        {2 * leaf.coords[0] + static_cast<std::uint32_t>(o[0]),
                         2 * leaf.coords[1] + static_cast<std::uint32_t>(o[1]),
                         2 * leaf.coords[2] + static_cast<std::uint32_t>(o[2])}};
    nodes_.emplace(child, true);
    fresh_.push_back(child);
  }
}

std::vector<CellKey> LeafTree::balance() {
  std::deque<CellKey> queue;
  std::vector<CellKey> candidates;
  if (rooted_) {
    candidates = leaves();
  } else {
    std::sort(fresh_.begin(), fresh_.end());
    fresh_.erase(std::unique(fresh_.begin(), fresh_.end()), fresh_.end());
    for (const CellKey& key : fresh_)
      if (const auto it = nodes_.find(key); it != nodes_.end() && it->second) candidates.push_back(key);
  }
  for (const CellKey& key : candidates)
    if (key.depth >= min_depth_ + 2) queue.push_back(key);
  std::vector<CellKey> splits;
  while (!queue.empty()) {
    const CellKey key = queue.front();
    queue.pop_front();
    for (const auto& offset : face_edge_offsets()) {
      LatticePoint n = key.coords;
      for (int a = 0; a < 3; ++a) n[a] += static_cast<std::uint32_t>(offset[a]);
      for (;;) {
        const Found found = locate(key.depth, n);
        if (found.where != Where::Leaf || found.depth >= key.depth - 1) break;
        const CellKey coarse{found.depth, ancestor(n, key.depth - found.depth)};
        split(coarse);
        splits.push_back(coarse);
        for (const auto& o : cube::kCorner)
          if (coarse.depth + 1 >= min_depth_ + 2)
            queue.push_back(CellKey{coarse.depth + 1,
                                    {2 * coarse.coords[0] + static_cast<std::uint32_t>(o[0]),
                                     2 * coarse.coords[1] + static_cast<std::uint32_t>(o[1]),
                                     2 * coarse.coords[2] + static_cast<std::uint32_t>(o[2])}});
      }
    }
  }
  // The children of the splits above were checked in the loop.
  fresh_.clear();
  rooted_ = false;
  return splits;
}

std::vector<CellKey> LeafTree::leaves() const {
  std::vector<CellKey> out;
  for (const auto& [key, leaf] : nodes_)
    if (leaf) out.push_back(key);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace isopatch
