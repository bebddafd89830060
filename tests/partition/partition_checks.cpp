#include "partition_checks.hpp"

#include "partition/cell.hpp"
#include "partition/cell_tests.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace isopatch::test {

bool segment_on_face(const SegmentKey& s, const FaceId& f) {
  if (s.axis == f.axis || s.start[f.axis] != f.plane()) return false;
  for (std::uint32_t a = 0; a < 3; ++a) {
    if (a == f.axis) continue;
    const std::uint32_t lo = s.start[a];
    const std::uint32_t hi = a == s.axis ? lo + s.length : lo;
    if (lo < f.lower[a] || hi > f.lower[a] + f.size) return false;
  }
  return true;
}

void expect_partition_invariants(const Surface& surface, const Partition& p) {
  const auto n = static_cast<std::uint32_t>(p.crossings.size());
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<FaceId, std::size_t>> sides;  // -> face, leaf
  std::vector<std::set<std::size_t>> users(n);
  for (std::size_t l = 0; l < p.leaves.size(); ++l) {
    const Leaf& leaf = p.leaves[l];
    const Cell cell = Cell::make(p.lattice, leaf.depth, leaf.coords);
    EXPECT_EQ(leaf.depth, p.surface_depth);
    if (leaf.kind == LeafKind::Simple) {
      EXPECT_EQ(leaf.reason, ComplexReason::None);
      EXPECT_EQ(leaf.loops.size(), 1u);
    } else {
      EXPECT_NE(leaf.reason, ComplexReason::None);
    }
    std::set<FaceId> cell_faces;
    for (int f = 0; f < 6; ++f) cell_faces.insert(cell.face(f));
    for (const Loop& loop : leaf.loops) {
      const std::size_t m = loop.corners.size();
      ASSERT_GE(m, 3u);
      ASSERT_EQ(loop.side_faces.size(), m);
      EXPECT_EQ(std::set<std::uint32_t>(loop.corners.begin(), loop.corners.end()).size(), m);
      std::vector<Vec3> points;
      Vec3 gradient = Vec3::Zero();
      for (std::size_t k = 0; k < m; ++k) {
        const std::uint32_t a = loop.corners[k];
        const std::uint32_t b = loop.corners[(k + 1) % m];
        ASSERT_LT(a, n);
        ASSERT_LT(b, n);
        users[a].insert(l);
        const FaceId& face = loop.side_faces[k];
        EXPECT_TRUE(cell_faces.count(face));
        EXPECT_TRUE(segment_on_face(p.crossings[a].segment, face));
        EXPECT_TRUE(segment_on_face(p.crossings[b].segment, face));
        EXPECT_TRUE(sides.emplace(std::pair{a, b}, std::pair{face, l}).second) << "side used twice";
        points.push_back(p.crossings[a].position);
        gradient += p.crossings[a].gradient.normalized();
      }
      if (leaf.kind == LeafKind::Simple) {
        EXPECT_GT(newell_normal(points).dot(gradient), 0.0);
      }
    }
  }
  for (const auto& [side, face_leaf] : sides) {
    const auto reverse = sides.find({side.second, side.first});
    ASSERT_NE(reverse, sides.end()) << "side " << side.first << "->" << side.second << " has no twin";
    EXPECT_EQ(reverse->second.first, face_leaf.first);
    EXPECT_NE(reverse->second.second, face_leaf.second);
  }

  // Leaves around each crossing's segment.
  std::map<LatticePoint, std::size_t> leaf_at;
  for (std::size_t l = 0; l < p.leaves.size(); ++l) leaf_at[p.leaves[l].coords] = l;
  const std::uint32_t step = p.lattice.step(p.surface_depth);
  for (std::uint32_t c = 0; c < n; ++c) {
    const Crossing& x = p.crossings[c];
    if (c > 0) {
      EXPECT_LT(p.crossings[c - 1].segment, x.segment);
    }
    ASSERT_EQ(x.segment.length, step);
    std::set<std::size_t> expected;
    const std::uint32_t u = (x.segment.axis + 1) % 3;
    const std::uint32_t v = (x.segment.axis + 2) % 3;
    for (std::uint32_t du = 0; du < 2; ++du) {
      for (std::uint32_t dv = 0; dv < 2; ++dv) {
        LatticePoint lower = x.segment.start;
        ASSERT_GE(lower[u], du * step);
        ASSERT_GE(lower[v], dv * step);
        lower[u] -= du * step;
        lower[v] -= dv * step;
        const LatticePoint coords{lower[0] / step, lower[1] / step, lower[2] / step};
        const auto it = leaf_at.find(coords);
        EXPECT_NE(it, leaf_at.end()) << "a cell around crossing " << c << " is not a leaf";
        if (it != leaf_at.end()) expected.insert(it->second);
      }
    }
    EXPECT_EQ(users[c], expected) << "crossing " << c;

    const Vec3 a = p.lattice.point(x.segment.start);
    const Vec3 b = p.lattice.point(x.segment.end());
    // Within 1e-12 cell sizes of a root along the edge: f changes sign across that neighbourhood.
    const Vec3 delta = 1e-12 * p.cell_size * x.direction;
    EXPECT_LT(surface.value(x.position - delta), 0.0) << "crossing " << c;
    EXPECT_GE(surface.value(x.position + delta), 0.0) << "crossing " << c;
    EXPECT_LE((x.position - a).norm() + (x.position - b).norm(), (b - a).norm() * (1 + 1e-12));
    EXPECT_NEAR(x.direction.norm(), 1.0, 1e-14);
    const bool start_negative = surface.value(a) < 0.0;
    EXPECT_NE(start_negative, surface.value(b) < 0.0);
    EXPECT_GT(x.direction.dot(start_negative ? b - a : a - b), 0.0);
  }
}

long euler_characteristic(const Partition& p) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  long faces = 0;
  for (const Leaf& leaf : p.leaves) {
    for (const Loop& loop : leaf.loops) {
      ++faces;
      for (std::size_t k = 0; k < loop.corners.size(); ++k) {
        const auto a = loop.corners[k];
        const auto b = loop.corners[(k + 1) % loop.corners.size()];
        edges.insert({std::min(a, b), std::max(a, b)});
      }
    }
  }
  return static_cast<long>(p.crossings.size()) - static_cast<long>(edges.size()) + faces;
}

}  // namespace isopatch::test
