// The adaptive partition (transition faces, flat corners, 2:1 balance): the invariants that make the
// assembled mesh closed and oriented, and the topology of the loop complex; plus its building blocks.
#include "partition/face_links.hpp"
#include "partition/leaf_tree.hpp"
#include "partition/partition.hpp"
#include "partition_checks.hpp"
#include "test_surfaces.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace isopatch {
namespace {

// The face is a face of the cell or a quarter of one.
bool face_of_cell(const Partition& p, const Leaf& leaf, const FaceId& f) {
  const std::uint32_t step = p.lattice.step(leaf.depth);
  if (f.size != step && 2 * f.size != step) return false;
  for (std::uint32_t a = 0; a < 3; ++a) {
    const std::uint32_t lo = leaf.coords[a] * step;
    if (a == f.axis) {
      if (f.lower[a] != lo && f.lower[a] != lo + step) return false;
    } else if (f.lower[a] < lo || f.lower[a] + f.size > lo + step || (f.lower[a] - lo) % f.size != 0) {
      return false;
    }
  }
  return true;
}

LatticePoint ancestor(const LatticePoint& c, int levels) {
  return {c[0] >> levels, c[1] >> levels, c[2] >> levels};
}

void expect_adaptive_invariants(const Surface& surface, const Partition& p) {
  ASSERT_TRUE(p.adaptive);
  std::set<CellKey> keys;
  for (const Leaf& leaf : p.leaves) EXPECT_TRUE(keys.insert(CellKey{leaf.depth, leaf.coords}).second);
  // 2:1 balance across faces and edges: no face or edge neighbour is two or more levels coarser (the
  // symmetric case is the same check from the finer leaf).
  for (const Leaf& leaf : p.leaves) {
    for (const auto& o : face_edge_offsets()) {
      LatticePoint n = leaf.coords;
      for (int a = 0; a < 3; ++a) n[a] += static_cast<std::uint32_t>(o[a]);
      for (int d = p.surface_depth; d < leaf.depth - 1; ++d)
        EXPECT_FALSE(keys.count(CellKey{d, ancestor(n, leaf.depth - d)}))
            << "unbalanced at depth " << leaf.depth;
    }
  }
  const auto n = static_cast<std::uint32_t>(p.crossings.size());
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<FaceId, std::size_t>> sides;
  std::vector<int> finest_user(n, -1);
  for (std::size_t l = 0; l < p.leaves.size(); ++l) {
    const Leaf& leaf = p.leaves[l];
    if (leaf.kind == LeafKind::Simple) {
      EXPECT_EQ(leaf.loops.size(), 1u);
    }
    if (leaf.depth < p.lattice.max_depth) {
      // Below max_depth only face / cone failures may remain (the others split).
      EXPECT_TRUE(leaf.reason == ComplexReason::None || leaf.reason == ComplexReason::FaceTest ||
                  leaf.reason == ComplexReason::NormalCone)
          << to_string(leaf.reason);
      EXPECT_EQ(leaf.loops.size(), 1u);
    }
    for (const Loop& loop : leaf.loops) {
      const std::size_t m = loop.corners.size();
      ASSERT_GE(m, 3u);
      ASSERT_LE(m, 12u);
      ASSERT_EQ(loop.side_faces.size(), m);
      EXPECT_EQ(std::set<std::uint32_t>(loop.corners.begin(), loop.corners.end()).size(), m);
      for (std::size_t k = 0; k < m; ++k) {
        const std::uint32_t a = loop.corners[k];
        const std::uint32_t b = loop.corners[(k + 1) % m];
        ASSERT_LT(a, n);
        ASSERT_LT(b, n);
        finest_user[a] = std::max(finest_user[a], leaf.depth);
        const FaceId& face = loop.side_faces[k];
        EXPECT_TRUE(face_of_cell(p, leaf, face));
        EXPECT_TRUE(test::segment_on_face(p.crossings[a].segment, face));
        EXPECT_TRUE(test::segment_on_face(p.crossings[b].segment, face));
        EXPECT_TRUE(sides.emplace(std::pair{a, b}, std::pair{face, l}).second) << "side used twice";
      }
    }
  }
  for (const auto& [side, face_leaf] : sides) {
    const auto reverse = sides.find({side.second, side.first});
    ASSERT_NE(reverse, sides.end()) << "side " << side.first << "->" << side.second << " has no twin";
    EXPECT_EQ(reverse->second.first, face_leaf.first);
    EXPECT_NE(reverse->second.second, face_leaf.second);
  }
  for (std::uint32_t c = 0; c < n; ++c) {
    const Crossing& x = p.crossings[c];
    if (c > 0) {
      EXPECT_LT(p.crossings[c - 1].segment, x.segment);
    }
    // Keyed by the finest segment: the edge of the deepest leaf using it.
    ASSERT_GE(finest_user[c], 0) << "unused crossing";
    EXPECT_EQ(x.segment.length, p.lattice.step(finest_user[c]));
    const Vec3 delta = 1e-12 * p.cell_size * x.direction;
    EXPECT_LT(surface.value(x.position - delta), 0.0) << "crossing " << c;
    EXPECT_GE(surface.value(x.position + delta), 0.0) << "crossing " << c;
  }
}

// Leaves with a corner whose segment is not an edge of the leaf (it lies inside one of its faces).
std::uint64_t leaves_with_flat_corners(const Partition& p) {
  std::uint64_t count = 0;
  for (const Leaf& leaf : p.leaves) {
    const std::uint32_t step = p.lattice.step(leaf.depth);
    bool flat = false;
    for (const Loop& loop : leaf.loops) {
      for (std::uint32_t c : loop.corners) {
        const SegmentKey& s = p.crossings[c].segment;
        int on_planes = 0;
        for (std::uint32_t a = 0; a < 3; ++a)
          if (a != s.axis && s.start[a] % step == 0) ++on_planes;
        flat = flat || on_planes < 2;
      }
    }
    if (flat) ++count;
  }
  return count;
}

struct AdaptiveCase {
  std::string name;
  SurfacePtr surface;
  long euler;
  int depth;
};

TEST(AdaptivePartition, InvariantsWithForcedSplits) {
  const std::vector<AdaptiveCase> cases = {{"sphere", test::sphere(), 2, 4},
                                           {"torus", test::torus(), 0, 4},
                                           {"tanglecube", test::tanglecube(), -8, 4},
                                           {"genus2", test::genus2(), -2, 5}};
  for (const AdaptiveCase& c : cases) {
    SCOPED_TRACE(c.name);
    PartitionSettings settings;
    settings.surface_depth = c.depth;
    settings.max_depth = c.depth + 3;
    const Partition uniform = build_partition(*c.surface, c.surface->box(), settings);
    settings.adaptive = true;
    for (std::size_t i = 0; i < uniform.leaves.size(); i += 7)
      settings.force_split.push_back(CellKey{uniform.leaves[i].depth, uniform.leaves[i].coords});
    // A cluster: a cell two levels down inside a leaf, so the balance ripples around it.
    const Leaf& middle = uniform.leaves[uniform.leaves.size() / 2];
    settings.force_split.push_back(
        CellKey{c.depth + 2, {4 * middle.coords[0] + 1, 4 * middle.coords[1] + 2, 4 * middle.coords[2] + 1}});
    const auto start = std::chrono::steady_clock::now();
    const Partition p = build_partition(*c.surface, c.surface->box(), settings);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << c.name << " adaptive " << c.depth << ".." << settings.max_depth << ": leaves "
              << p.leaves.size() << " per depth";
    int depths = 0;
    for (int d = 0; d <= Lattice::kMaxDepth; ++d) {
      if (p.stats.leaves_per_depth[d] == 0) continue;
      ++depths;
      std::cout << " [" << d << "] " << p.stats.leaves_per_depth[d];
    }
    std::cout << ", flat " << p.stats.leaves_with_flat_corners << ", max loop " << p.stats.max_loop_size
              << ", rounds " << p.stats.adaptive_rounds << ", splits forced/topology/balance "
              << p.stats.forced_splits << "/" << p.stats.topology_splits << "/" << p.stats.balance_splits
              << ", simple " << p.stats.simple_leaves << ", euler " << test::euler_characteristic(p) << ", "
              << seconds << " s\n";
    EXPECT_GE(depths, 3);
    EXPECT_GT(p.stats.leaves_with_flat_corners, 0u);
    EXPECT_EQ(leaves_with_flat_corners(p), p.stats.leaves_with_flat_corners);
    EXPECT_GT(p.stats.max_loop_size, 6u);
    expect_adaptive_invariants(*c.surface, p);
    EXPECT_EQ(test::euler_characteristic(p), c.euler);
  }
}

TEST(AdaptivePartition, WithoutForcedSplitsRefinesOnlyDoubtfulLeaves) {
  const auto surface = test::tanglecube();
  PartitionSettings settings;
  settings.surface_depth = 3;
  settings.max_depth = 6;
  settings.adaptive = true;
  const Partition p = build_partition(*surface, surface->box(), settings);
  expect_adaptive_invariants(*surface, p);
  EXPECT_EQ(test::euler_characteristic(p), -8);
  EXPECT_EQ(p.stats.forced_splits, 0u);
}

TEST(AdaptivePartition, IsDeterministic) {
  const auto surface = test::torus();
  PartitionSettings settings;
  settings.surface_depth = 4;
  settings.max_depth = 6;
  settings.adaptive = true;
  settings.force_split = {CellKey{4, {3, 5, 1}}, CellKey{5, {20, 9, 4}}};
  const Partition a = build_partition(*surface, surface->box(), settings);
  const Partition b = build_partition(*surface, surface->box(), settings);
  ASSERT_EQ(a.leaves.size(), b.leaves.size());
  ASSERT_EQ(a.crossings.size(), b.crossings.size());
  for (std::size_t l = 0; l < a.leaves.size(); ++l) {
    EXPECT_EQ(a.leaves[l].depth, b.leaves[l].depth);
    EXPECT_EQ(a.leaves[l].coords, b.leaves[l].coords);
    ASSERT_EQ(a.leaves[l].loops.size(), b.leaves[l].loops.size());
    for (std::size_t k = 0; k < a.leaves[l].loops.size(); ++k)
      EXPECT_EQ(a.leaves[l].loops[k].corners, b.leaves[l].loops[k].corners);
  }
}

TEST(AdaptivePartition, UniformModeIgnoresForceSplit) {
  const auto surface = test::sphere();
  PartitionSettings settings;
  settings.surface_depth = 4;
  settings.max_depth = 6;
  const Partition a = build_partition(*surface, surface->box(), settings);
  settings.force_split = {CellKey{4, {3, 5, 1}}};
  const Partition b = build_partition(*surface, surface->box(), settings);
  EXPECT_FALSE(a.adaptive);
  ASSERT_EQ(a.leaves.size(), b.leaves.size());
  ASSERT_EQ(a.crossings.size(), b.crossings.size());
  for (std::size_t l = 0; l < a.leaves.size(); ++l) EXPECT_EQ(a.leaves[l].depth, 4);
}

TEST(FaceLinks, LinksTwoCrossingsWithNegativeOnTheRight) {
  // Square 0,1,2,3 with vertex 1 negative: segments 0 (0-1) and 1 (1-2) crossed; the negative vertex
  // right after segment 0, so the side runs 0 -> 1.
  const std::array<bool, 4> one{false, true, false, false};
  const FaceLinks links = link_face(one, false);
  ASSERT_EQ(links.sides.size(), 1u);
  EXPECT_EQ(links.sides[0].from, 0);
  EXPECT_EQ(links.sides[0].to, 1);
  EXPECT_FALSE(links.ambiguous);
  // A transition polygon (midpoint on segment 1): 5 vertices, negative vertices 2 and 3.
  const std::array<bool, 5> five{false, false, true, true, false};
  const FaceLinks five_links = link_face(five, false);
  ASSERT_EQ(five_links.sides.size(), 1u);
  EXPECT_EQ(five_links.sides[0].from, 1);
  EXPECT_EQ(five_links.sides[0].to, 3);
}

TEST(FaceLinks, AmbiguousPolygons) {
  const std::array<bool, 4> diagonal{true, false, true, false};
  const FaceLinks by_centre_negative = link_face(diagonal, true);
  EXPECT_TRUE(by_centre_negative.ambiguous);
  EXPECT_FALSE(by_centre_negative.unresolved);
  ASSERT_EQ(by_centre_negative.sides.size(), 2u);
  // The same face seen from the other side (reversed polygon) makes the same, reversed, links.
  const std::array<bool, 4> reversed{true, false, true, false};  // vertices 0, 3, 2, 1
  const FaceLinks other = link_face(reversed, true);
  ASSERT_EQ(other.sides.size(), 2u);
  const std::array<bool, 6> six{true, false, true, false, false, false};
  const FaceLinks unresolved = link_face(six, false);
  EXPECT_TRUE(unresolved.ambiguous);
  EXPECT_TRUE(unresolved.unresolved);
  EXPECT_TRUE(unresolved.sides.empty());
}

TEST(LeafTree, BalanceAcrossFacesAndEdges) {
  LeafTree tree(2, 6);
  for (std::uint32_t x = 0; x < 4; ++x)
    for (std::uint32_t y = 0; y < 4; ++y)
      for (std::uint32_t z = 0; z < 4; ++z) tree.add_root({x, y, z});
  CellKey key{2, {1, 1, 1}};
  for (int d = 2; d < 6; ++d) {
    tree.split(key);
    key = CellKey{d + 1, {2 * key.coords[0], 2 * key.coords[1], 2 * key.coords[2]}};
  }
  EXPECT_FALSE(tree.balance().empty());
  for (const CellKey& leaf : tree.leaves()) {
    for (const auto& o : face_edge_offsets()) {
      LatticePoint n = leaf.coords;
      for (int a = 0; a < 3; ++a) n[a] += static_cast<std::uint32_t>(o[a]);
      const LeafTree::Found found = tree.locate(leaf.depth, n);
      if (found.where == LeafTree::Where::Leaf) {
        EXPECT_GE(found.depth, leaf.depth - 1);
      }
    }
  }
  EXPECT_TRUE(tree.balance().empty());
  EXPECT_FALSE(tree.add_root({1, 1, 1}));
  EXPECT_EQ(tree.locate(6, {8, 8, 8}).where, LeafTree::Where::Leaf);
  EXPECT_EQ(tree.locate(3, {2, 2, 2}).where, LeafTree::Where::Split);
  EXPECT_EQ(tree.locate(2, {4, 0, 0}).where, LeafTree::Where::Outside);
}

}  // namespace
}  // namespace isopatch

namespace isopatch {
namespace {

// Coarse starts (topology splits and max_depth leaves with ambiguous faces) and deep forced cells.
TEST(AdaptivePartition, InvariantsFromCoarseStarts) {
  const std::vector<AdaptiveCase> cases = {{"sphere", test::sphere(0.7, Vec3(0.1, -0.05, 0.2)), 2, 0},
                                           {"torus", test::torus(), 0, 0},
                                           {"tanglecube", test::tanglecube(), -8, 0},
                                           {"genus2", test::genus2(), -2, 0}};
  for (const AdaptiveCase& c : cases) {
    for (const auto& [s, max] : {std::pair{2, 5}, std::pair{3, 5}, std::pair{3, 6}}) {
      SCOPED_TRACE(c.name + " " + std::to_string(s) + ".." + std::to_string(max));
      PartitionSettings settings;
      settings.surface_depth = s;
      settings.max_depth = max;
      settings.adaptive = true;
      const Partition first = build_partition(*c.surface, c.surface->box(), settings);
      for (std::size_t i = 0; i < first.leaves.size(); i += 3)
        settings.force_split.push_back(CellKey{first.leaves[i].depth, first.leaves[i].coords});
      const Partition p = build_partition(*c.surface, c.surface->box(), settings);
      expect_adaptive_invariants(*c.surface, first);
      expect_adaptive_invariants(*c.surface, p);
      std::cout << c.name << " " << s << ".." << max << ": leaves " << first.leaves.size() << " -> "
                << p.leaves.size() << ", euler " << test::euler_characteristic(first) << " -> "
                << test::euler_characteristic(p) << ", max loop " << p.stats.max_loop_size << ", complex";
      for (int r = 1; r < kComplexReasonCount; ++r)
        if (p.stats.complex_by_reason[r] > 0)
          std::cout << " " << to_string(static_cast<ComplexReason>(r)) << " " << p.stats.complex_by_reason[r];
      std::cout << "\n";
      EXPECT_EQ(test::euler_characteristic(first), c.euler);
      EXPECT_EQ(test::euler_characteristic(p), c.euler);
    }
  }
}

}  // namespace
}  // namespace isopatch

namespace isopatch {
namespace {

// Rotates a loop to start at its smallest corner, so loops can be compared as cycles.
std::vector<std::uint32_t> canonical(std::vector<std::uint32_t> corners) {
  std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
  return corners;
}

// Where nothing needs splitting, the adaptive partition is the uniform one: same leaves, bit-identical
// crossings, same loops (as cycles) and verdicts.
TEST(AdaptivePartition, EqualsUniformWhenNothingSplits) {
  const auto surface = test::torus();
  PartitionSettings settings;
  settings.surface_depth = 5;
  settings.max_depth = 7;
  const Partition u = build_partition(*surface, surface->box(), settings);
  settings.adaptive = true;
  const Partition a = build_partition(*surface, surface->box(), settings);
  ASSERT_EQ(a.stats.topology_splits + a.stats.balance_splits, 0u);
  ASSERT_EQ(a.leaves.size(), u.leaves.size());
  ASSERT_EQ(a.crossings.size(), u.crossings.size());
  for (std::size_t c = 0; c < a.crossings.size(); ++c) {
    EXPECT_EQ(a.crossings[c].segment, u.crossings[c].segment);
    EXPECT_EQ(a.crossings[c].position, u.crossings[c].position);
  }
  for (std::size_t l = 0; l < a.leaves.size(); ++l) {
    EXPECT_EQ(a.leaves[l].coords, u.leaves[l].coords);
    EXPECT_EQ(a.leaves[l].reason, u.leaves[l].reason);
    EXPECT_EQ(a.leaves[l].config, u.leaves[l].config);
    ASSERT_EQ(a.leaves[l].loops.size(), 1u);
    ASSERT_EQ(u.leaves[l].loops.size(), 1u);
    EXPECT_EQ(canonical(a.leaves[l].loops[0].corners), canonical(u.leaves[l].loops[0].corners));
  }
  EXPECT_EQ(a.stats.simple_leaves, u.stats.simple_leaves);
}

}  // namespace
}  // namespace isopatch
