// Cutting a base into blocks along the Morton curve and numbering the output (blocks.hpp).
#include <isopatch/blocks.hpp>
#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <string>

#include "core/spatial_order.hpp"
#include "refine/base_edges.hpp"
#include "refine/lattice_layout.hpp"

namespace isopatch {
namespace {

/// The Morton code of p in `box`, each axis quantised to 2^21 steps (core/spatial_order.hpp).
std::uint64_t morton(const Vec3& p, const Box& box) {
  std::uint32_t cell[3];
  const double steps = 2097151.0;  // 2^21 - 1
  for (int a = 0; a < 3; ++a) {
    const double extent = box.hi[a] - box.lo[a];
    const double u = extent > 0.0 ? std::clamp((p[a] - box.lo[a]) / extent, 0.0, 1.0) : 0.0;
    cell[a] = static_cast<std::uint32_t>(std::floor(u * steps));
  }
  return z_order_key(cell[0], cell[1], cell[2]);
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

/// Per base triangle, its group: the lowest triangle of the triangles of one patch around a held
/// vertex (a composite's corner; stars that share a triangle joined), or the triangle itself.
std::vector<std::uint32_t> star_groups(const Mesh& base, const BasePatches& patches) {
  std::vector<std::uint32_t> parent(base.triangle_count());
  std::iota(parent.begin(), parent.end(), 0U);
  if (patches.triangle_patch.empty()) return parent;
  const auto find = [&](std::uint32_t t) {
    while (parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
  };
  // A composite's corners: the ends of its curves, where two or more curves meet.
  std::vector<std::uint8_t> held(base.vertex_count(), 0);
  for (const std::vector<std::uint32_t>& curve : patches.curve_vertices)
    if (!curve.empty()) {
      if (curve.front() >= base.vertex_count() || curve.back() >= base.vertex_count())
        throw InputError("a curve names a vertex the base does not have", "patches");
      held[curve.front()] = held[curve.back()] = 1;
    }
  // Per held vertex and patch, the first triangle met: the later ones join it.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> first;
  for (std::uint32_t t = 0; t < base.triangle_count(); ++t)
    for (const std::uint32_t v : base.triangles[t]) {
      if (!held[v]) continue;
      const auto [at, fresh] = first.try_emplace({v, patches.triangle_patch[t]}, t);
      if (fresh) continue;
      const std::uint32_t a = find(at->second), b = find(t);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  for (std::uint32_t t = 0; t < base.triangle_count(); ++t) parent[t] = find(t);
  return parent;
}

/// The first position in `order` of each block: the even cuts, each moved to the nearest start of a
/// patch within a quarter of a block (a seam along a curve takes the curve's own points, as one process
/// does), then past the group it would split. \throw InputError when a block would be empty.
std::vector<std::size_t> block_starts(const std::vector<std::uint32_t>& order,
                                      const std::vector<std::uint32_t>& patch,
                                      const std::vector<std::uint32_t>& group, int blocks) {
  const std::size_t count = order.size();
  std::vector<std::size_t> patch_starts;
  for (std::size_t i = 1; i < count; ++i)
    if (patch[order[i]] != patch[order[i - 1]]) patch_starts.push_back(i);
  std::vector<std::size_t> starts{0};
  const std::size_t reach = count / (4 * static_cast<std::size_t>(blocks));
  for (std::size_t j = 1; j < static_cast<std::size_t>(blocks); ++j) {
    // The first i with i * blocks / count >= j (the even cut of a base of one function).
    std::size_t cut = (j * count + static_cast<std::size_t>(blocks) - 1) / static_cast<std::size_t>(blocks);
    const auto next = std::lower_bound(patch_starts.begin(), patch_starts.end(), cut);
    std::size_t best = cut, distance = reach + 1;
    if (next != patch_starts.end() && *next - cut < distance) best = *next, distance = *next - cut;
    if (next != patch_starts.begin() && cut - *(next - 1) < distance) best = *(next - 1);
    cut = best;
    while (cut < count && cut > 0 && group[order[cut]] == group[order[cut - 1]]) ++cut;
    if (cut <= starts.back() || cut >= count)
      throw InputError(std::to_string(blocks) + " blocks are too many for a base of " +
                           std::to_string(count) +
                           " triangles whose corners keep their triangles in one block: use fewer",
                       "tiles");
    starts.push_back(cut);
  }
  return starts;
}

}  // namespace

BlockPlan plan_blocks(const Mesh& base, int level, int blocks, const BasePatches& patches) {
  check_plan_input(base, level, blocks);
  const std::size_t count = base.triangle_count();
  const Box box = bounding_box(base);
  std::vector<std::uint64_t> code(count);
  for (std::size_t t = 0; t < count; ++t) {
    const Triangle& tri = base.triangles[t];
    code[t] = morton((base.positions[tri[0]] + base.positions[tri[1]] + base.positions[tri[2]]) / 3.0, box);
  }
  // A composite's triangles sort patch by patch (patches at their lowest code), and a group (a corner's
  // triangles in one patch) as one, at its lowest code; a base of one function by code alone.
  std::vector<std::uint32_t> patch(count, 0);
  if (!patches.triangle_patch.empty()) {
    if (patches.triangle_patch.size() != count)
      throw InputError("the patches name " + std::to_string(patches.triangle_patch.size()) +
                           " triangles, the base has " + std::to_string(count),
                       "patches");
    patch = patches.triangle_patch;
  }
  const std::vector<std::uint32_t> group = star_groups(base, patches);
  std::map<std::uint32_t, std::uint64_t> patch_code;
  std::vector<std::uint64_t> group_code(code);
  for (std::size_t t = 0; t < count; ++t) {
    group_code[group[t]] = std::min(group_code[group[t]], code[t]);
    const auto [at, fresh] = patch_code.try_emplace(patch[t], code[t]);
    if (!fresh) at->second = std::min(at->second, code[t]);
  }
  std::vector<std::uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0U);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const std::uint64_t pa = patch_code.at(patch[a]), pb = patch_code.at(patch[b]);
    if (pa != pb) return pa < pb;
    if (patch[a] != patch[b]) return patch[a] < patch[b];
    const std::uint32_t ga = group[a], gb = group[b];
    if (group_code[ga] != group_code[gb]) return group_code[ga] < group_code[gb];
    return ga != gb ? ga < gb : a < b;
  });
  BlockPlan plan;
  plan.level = level;
  plan.blocks = blocks;
  const std::vector<std::size_t> starts = block_starts(order, patch, group, blocks);
  // Reusing `order`'s storage (a fresh vector of `count` zeros trips GCC 12's -Wnull-dereference here).
  std::vector<std::uint32_t> block_of = order;
  std::size_t b = 0;
  for (std::size_t i = 0; i < count; ++i) {
    while (b + 1 < starts.size() && i >= starts[b + 1]) ++b;
    block_of[order[i]] = static_cast<std::uint32_t>(b);
  }
  plan.triangle_block = std::move(block_of);

  number_output(base, level, plan);
  return plan;
}

}  // namespace isopatch
