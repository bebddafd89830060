// The refinement's numbering: shared edge points, counts, orientation and a closed result.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <utility>

#include "refine/base_edges.hpp"
#include "refine/lattice_layout.hpp"

namespace isopatch::refine {
namespace {

/// A tetrahedron with outward counter-clockwise triangles: closed, every edge used twice.
Mesh tetrahedron() {
  Mesh m;
  m.positions = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return m;
}

std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed_edges(
    const std::vector<Triangle>& triangles) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i)
      ++uses[{t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)]}];
  return uses;
}

TEST(BaseEdges, NumbersEachEdgeOnceInSortedOrder) {
  const Mesh m = tetrahedron();
  const BaseEdges e = base_edges(m);
  ASSERT_EQ(e.size(), 6u);
  for (std::size_t i = 0; i < e.size(); ++i) {
    EXPECT_LT(e.ends[i][0], e.ends[i][1]);
    EXPECT_EQ(e.uses[i], 2);
    if (i > 0) {
      EXPECT_LT(e.ends[i - 1], e.ends[i]);
    }
  }
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (std::size_t s = 0; s < 3; ++s) {
      const auto& ends = e.ends[e.of_triangle[t][s]];
      const std::set<std::uint32_t> side{m.triangles[t][s], m.triangles[t][(s + 1) % 3]};
      EXPECT_EQ(side, (std::set<std::uint32_t>{ends[0], ends[1]}));
    }
}

TEST(LatticeLayout, RefinedClosedMeshIsClosedOrientedAndRegular) {
  const Mesh m = tetrahedron();
  const BaseEdges e = base_edges(m);
  for (int k : {1, 2, 3, 5, 8}) {
    const LatticeLayout layout(m, e, k);
    EXPECT_EQ(layout.vertex_count(), 4u + 6u * static_cast<std::size_t>(k - 1) +
                                         4u * static_cast<std::size_t>((k - 1) * (k - 2) / 2));
    std::vector<Triangle> triangles(layout.triangle_count());
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      layout.emit_triangles(t, triangles.data() + t * static_cast<std::size_t>(k * k));
    // Every directed edge once and its reverse once: closed and consistently oriented, no welding.
    const auto uses = directed_edges(triangles);
    for (const auto& [edge, n] : uses) {
      EXPECT_EQ(n, 1) << "k " << k;
      EXPECT_EQ(uses.count({edge.second, edge.first}), 1u) << "k " << k;
    }
    // Euler characteristic 2 with every vertex used; new vertices have valence 6, base ones keep 3.
    std::map<std::uint32_t, std::set<std::uint32_t>> ring;
    for (const auto& [edge, n] : uses) ring[edge.first].insert(edge.second);
    ASSERT_EQ(ring.size(), layout.vertex_count());
    const long v = static_cast<long>(layout.vertex_count()), f = static_cast<long>(triangles.size());
    EXPECT_EQ(v - static_cast<long>(uses.size()) / 2 + f, 2);
    for (const auto& [vertex, neighbours] : ring)
      EXPECT_EQ(neighbours.size(), vertex < 4 ? 3u : 6u) << "k " << k << " vertex " << vertex;
  }
}

TEST(LatticeLayout, BothTrianglesBesideAnEdgeUseTheSamePoints) {
  const Mesh m = tetrahedron();
  const BaseEdges e = base_edges(m);
  const int k = 4;
  const LatticeLayout layout(m, e, k);
  // Triangle 0 (0,1,2) side 0 runs 0 -> 1; triangle 1 (0,3,1) side 2 runs 1 -> 0: the point with weight
  // i/k on vertex 1 is (i, 0) in the first and (0, i) in the second.
  for (int i = 1; i < k; ++i) EXPECT_EQ(layout.vertex(0, i, 0), layout.vertex(1, 0, i));
}

}  // namespace
}  // namespace isopatch::refine
