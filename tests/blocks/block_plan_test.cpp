// Cutting a base into blocks and numbering the output (isopatch/blocks.hpp).
#include <gtest/gtest.h>

#include <isopatch/blocks.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>

#include <algorithm>
#include <numeric>
#include <vector>

namespace isopatch {
namespace {

Mesh torus_base() {
  const SurfacePtr torus = catalogue_surface("torus");
  Settings s;
  s.refine = 1;
  s.edge_length = 0.2;
  return mesh_surface(*torus, s);
}

TEST(BlockPlan, CountsAddUpToTheRefinedMeshAndEveryBlockGetsAboutAsManyTriangles) {
  const Mesh base = torus_base();
  const int k = 4;
  const BlockPlan plan = plan_blocks(base, k, 8);
  // A closed mesh: V + E (k - 1) + T (k - 1)(k - 2) / 2 vertices, T k^2 triangles.
  const std::uint64_t edges = base.triangle_count() * 3 / 2;
  EXPECT_EQ(plan.vertices,
            base.vertex_count() + edges * (k - 1) + base.triangle_count() * (k - 1) * (k - 2) / 2);
  EXPECT_EQ(plan.triangles, base.triangle_count() * k * k);
  std::uint64_t next = 0;
  for (int b = 0; b < 8; ++b) {
    EXPECT_EQ(plan.first_vertex[static_cast<std::size_t>(b)], next);
    next += plan.vertex_count[static_cast<std::size_t>(b)];
    const double share =
        static_cast<double>(plan.triangle_count[static_cast<std::size_t>(b)]) / plan.triangles;
    EXPECT_NEAR(share, 1.0 / 8.0, 1.0 / base.triangle_count());
  }
  EXPECT_EQ(
      std::accumulate(plan.owned_base_vertices.begin(), plan.owned_base_vertices.end(), std::uint64_t{0}),
      base.vertex_count());
  EXPECT_EQ(std::accumulate(plan.owned_edges.begin(), plan.owned_edges.end(), std::uint64_t{0}), edges);
}

TEST(BlockPlan, EveryOutputNumberIsGivenOnceAndInItsOwnersRange) {
  const Mesh base = torus_base();
  const int k = 4;
  const BlockPlan plan = plan_blocks(base, k, 8);
  std::vector<int> seen(plan.vertices, 0);
  for (const std::uint64_t v : plan.vertex_number) ++seen[v];
  for (const std::uint64_t first : plan.edge_first_number)
    for (int j = 0; j < k - 1; ++j) ++seen[first + static_cast<std::uint64_t>(j)];
  const std::uint64_t inner = (k - 1) * (k - 2) / 2;
  for (const std::uint64_t first : plan.triangle_first_inner)
    for (std::uint64_t m = 0; m < inner; ++m) ++seen[first + m];
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(plan.vertices));
  // A triangle's inner points are numbered in its own block's range.
  for (std::size_t t = 0; t < base.triangle_count(); ++t) {
    const std::size_t b = plan.triangle_block[t];
    EXPECT_GE(plan.triangle_first_inner[t], plan.first_vertex[b]);
    EXPECT_LE(plan.triangle_first_inner[t] + inner, plan.first_vertex[b] + plan.vertex_count[b]);
  }
  // Seams: exactly the edges whose two triangles are in different blocks.
  std::size_t between = 0;
  for (const std::uint8_t s : plan.edge_between_blocks) between += s;
  EXPECT_GT(between, 0U);
  EXPECT_LT(between, plan.edge_ends.size());
}

TEST(BlockPlan, BlocksAreCompactAlongTheMortonCurve) {
  const Mesh base = torus_base();
  const BlockPlan plan = plan_blocks(base, 2, 8);
  // Compact blocks share few edges: far fewer than a random cut (about 7/8 of all edges).
  std::size_t across = 0, total = 0;
  for (std::size_t t = 0; t < base.triangle_count(); ++t)
    for (std::size_t u = t + 1; u < base.triangle_count(); ++u) {
      int shared = 0;
      for (const std::uint32_t a : base.triangles[t])
        for (const std::uint32_t b : base.triangles[u]) shared += a == b ? 1 : 0;
      if (shared != 2) continue;
      ++total;
      if (plan.triangle_block[t] != plan.triangle_block[u]) ++across;
    }
  EXPECT_LT(static_cast<double>(across), 0.2 * static_cast<double>(total));
  EXPECT_EQ(plan_blocks(base, 2, 8).triangle_block, plan.triangle_block);  // depends on the base alone
}

TEST(BlockPlan, RefusesWhatCannotBeCut) {
  const Mesh base = torus_base();
  EXPECT_THROW(plan_blocks(Mesh{}, 2, 2), InputError);
  EXPECT_THROW(plan_blocks(base, 2, 0), InputError);
  EXPECT_THROW(plan_blocks(base, 2, static_cast<int>(base.triangle_count()) + 1), InputError);
  EXPECT_THROW(plan_blocks(base, 0, 2), InputError);
  EXPECT_THROW(plan_blocks(base, 33, 2), InputError);
}

}  // namespace
}  // namespace isopatch
