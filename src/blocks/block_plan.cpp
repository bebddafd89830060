// Cutting a base into blocks along the Morton curve and numbering the output (blocks.hpp).
#include <isopatch/blocks.hpp>
#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "refine/base_edges.hpp"
#include "refine/lattice_layout.hpp"

namespace isopatch {
namespace {

/// Bits per axis of the Morton code (3 x 21 = 63 bits).
constexpr int kMortonBits = 21;

/// The 21 low bits of v spread to every third bit.
std::uint64_t spread(std::uint64_t v) {
  v &= (std::uint64_t{1} << kMortonBits) - 1;
  v = (v | v << 32U) & 0x1f00000000ffffULL;
  v = (v | v << 16U) & 0x1f0000ff0000ffULL;
  v = (v | v << 8U) & 0x100f00f00f00f00fULL;
  v = (v | v << 4U) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2U) & 0x1249249249249249ULL;
  return v;
}

/// The Morton code of p in `box`, each axis quantised to 2^21 steps.
std::uint64_t morton(const Vec3& p, const Box& box) {
  std::uint64_t code = 0;
  const double steps = static_cast<double>((std::uint64_t{1} << kMortonBits) - 1);
  for (int a = 0; a < 3; ++a) {
    const double extent = box.hi[a] - box.lo[a];
    const double u = extent > 0.0 ? std::clamp((p[a] - box.lo[a]) / extent, 0.0, 1.0) : 0.0;
    code |= spread(static_cast<std::uint64_t>(std::floor(u * steps))) << static_cast<unsigned>(a);
  }
  return code;
}

void check_plan_input(const Mesh& base, int level, int blocks) {
  if (base.triangle_count() == 0) throw InputError("the base has no triangles to cut into blocks");
  if (level < 1 || level > refine::kMaxLevel)
    throw InputError("the refinement level must be 1.." + std::to_string(refine::kMaxLevel), "refine");
  if (blocks < 1 || static_cast<std::size_t>(blocks) > base.triangle_count())
    throw InputError("the number of blocks must be 1.." + std::to_string(base.triangle_count()) +
                         " (the base's triangles), not " + std::to_string(blocks),
                     "tiles");
  base.validate();
}

/// Numbers the output of `plan` (triangle_block set): the lowest block among the triangles around a
/// base vertex or edge owns it; a block's numbers are its base vertices, then the points of its edges,
/// then the inner points of its triangles, each in ascending base order (blocks.hpp).
void number_output(const Mesh& base, int level, BlockPlan& plan) {
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  const refine::BaseEdges edges = refine::base_edges(base);
  const auto n = static_cast<std::size_t>(plan.blocks);
  const auto k = static_cast<std::uint64_t>(level);
  const std::uint64_t inner = (k - 1) * (k >= 2 ? k - 2 : 0) / 2;
  std::vector<std::uint32_t> vertex_owner(base.vertex_count(), kNone), edge_owner(edges.size(), kNone);
  for (std::size_t t = 0; t < base.triangle_count(); ++t)
    for (std::size_t c = 0; c < 3; ++c) {
      std::uint32_t& v = vertex_owner[base.triangles[t][c]];
      v = std::min(v, plan.triangle_block[t]);
      std::uint32_t& e = edge_owner[edges.of_triangle[t][c]];
      e = std::min(e, plan.triangle_block[t]);
    }
  for (std::uint32_t& v : vertex_owner)
    if (v == kNone) v = 0;  // a vertex no triangle uses
  // Per block, how many of each it owns, then the numbers, block by block.
  std::vector<std::uint64_t> owned_triangles(n, 0);
  plan.owned_base_vertices.assign(n, 0);
  plan.owned_edges.assign(n, 0);
  for (const std::uint32_t o : vertex_owner) ++plan.owned_base_vertices[o];
  for (const std::uint32_t o : edge_owner) ++plan.owned_edges[o];
  for (const std::uint32_t b : plan.triangle_block) ++owned_triangles[b];
  plan.first_vertex.resize(n);
  plan.vertex_count.resize(n);
  plan.first_triangle.resize(n);
  plan.triangle_count.resize(n);
  constexpr std::uint64_t kMost = std::numeric_limits<std::uint64_t>::max() / 2;
  for (std::size_t b = 0; b < n; ++b) {
    plan.vertex_count[b] =
        plan.owned_base_vertices[b] + plan.owned_edges[b] * (k - 1) + owned_triangles[b] * inner;
    plan.triangle_count[b] = owned_triangles[b] * k * k;
    plan.first_vertex[b] = plan.vertices;
    plan.first_triangle[b] = plan.triangles;
    plan.vertices += plan.vertex_count[b];
    plan.triangles += plan.triangle_count[b];
    if (plan.vertices > kMost || plan.triangles > kMost)
      throw LimitError("the blocked output would need more than 2^63 vertex numbers", "tiles");
  }
  // The next number of each block's base vertices, edge points and inner points.
  std::vector<std::uint64_t> next_vertex(plan.first_vertex), next_edge(n), next_inner(n);
  for (std::size_t b = 0; b < n; ++b) {
    next_edge[b] = plan.first_vertex[b] + plan.owned_base_vertices[b];
    next_inner[b] = next_edge[b] + plan.owned_edges[b] * (k - 1);
  }
  plan.vertex_number.resize(base.vertex_count());
  for (std::size_t v = 0; v < base.vertex_count(); ++v)
    plan.vertex_number[v] = next_vertex[vertex_owner[v]]++;
  plan.edge_ends = edges.ends;
  plan.edge_first_number.resize(edges.size());
  plan.edge_between_blocks.assign(edges.size(), 0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    plan.edge_first_number[e] = next_edge[edge_owner[e]];
    next_edge[edge_owner[e]] += k - 1;
  }
  for (std::size_t t = 0; t < base.triangle_count(); ++t)
    for (std::size_t c = 0; c < 3; ++c) {
      const std::uint32_t e = edges.of_triangle[t][c];
      if (plan.triangle_block[t] != edge_owner[e]) plan.edge_between_blocks[e] = 1;
    }
  plan.triangle_first_inner.resize(base.triangle_count());
  for (std::size_t t = 0; t < base.triangle_count(); ++t) {
    plan.triangle_first_inner[t] = next_inner[plan.triangle_block[t]];
    next_inner[plan.triangle_block[t]] += inner;
  }
}

}  // namespace

BlockPlan plan_blocks(const Mesh& base, int level, int blocks) {
  check_plan_input(base, level, blocks);
  const std::size_t count = base.triangle_count();
  const Box box = bounding_box(base);
  std::vector<std::uint64_t> code(count);
  for (std::size_t t = 0; t < count; ++t) {
    const Triangle& tri = base.triangles[t];
    code[t] = morton((base.positions[tri[0]] + base.positions[tri[1]] + base.positions[tri[2]]) / 3.0, box);
  }
  std::vector<std::uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0U);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return code[a] != code[b] ? code[a] < code[b] : a < b; });
  BlockPlan plan;
  plan.level = level;
  plan.blocks = blocks;
  // Reusing `order`'s storage (a fresh vector of `count` zeros trips GCC 12's -Wnull-dereference here).
  std::vector<std::uint32_t> block_of = order;
  for (std::size_t i = 0; i < count; ++i)
    block_of[order[i]] = static_cast<std::uint32_t>(i * static_cast<std::size_t>(blocks) / count);
  plan.triangle_block = std::move(block_of);

  number_output(base, level, plan);
  return plan;
}

}  // namespace isopatch
