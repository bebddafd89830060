// Ownership of a blocked base's shared items (block_ownership.hpp).
#include "blocks/block_ownership.hpp"

#include <algorithm>
#include <limits>

namespace isopatch::blocks {

Ownership ownership(const Mesh& base, const refine::BaseEdges& edges,
                    std::span<const std::uint32_t> triangle_block, int blocks) {
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  const auto n = static_cast<std::size_t>(blocks);
  Ownership o;
  o.vertex_owner.assign(base.vertex_count(), kNone);
  o.edge_owner.assign(edges.size(), kNone);
  for (std::size_t t = 0; t < base.triangle_count(); ++t) {
    const std::uint32_t b = triangle_block[t];
    for (int c = 0; c < 3; ++c) {
      std::uint32_t& v = o.vertex_owner[base.triangles[t][static_cast<std::size_t>(c)]];
      v = std::min(v, b);
      std::uint32_t& e = o.edge_owner[edges.of_triangle[t][static_cast<std::size_t>(c)]];
      e = std::min(e, b);
    }
  }
  o.vertices.assign(n, 0);
  o.edges.assign(n, 0);
  o.triangles.assign(n, 0);
  o.vertex_rank.resize(base.vertex_count());
  for (std::size_t v = 0; v < base.vertex_count(); ++v) {
    if (o.vertex_owner[v] == kNone) o.vertex_owner[v] = 0;
    o.vertex_rank[v] = static_cast<std::uint32_t>(o.vertices[o.vertex_owner[v]]++);
  }
  o.edge_rank.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e)
    o.edge_rank[e] = static_cast<std::uint32_t>(o.edges[o.edge_owner[e]]++);
  o.triangle_rank.resize(base.triangle_count());
  for (std::size_t t = 0; t < base.triangle_count(); ++t)
    o.triangle_rank[t] = static_cast<std::uint32_t>(o.triangles[triangle_block[t]]++);
  return o;
}

}  // namespace isopatch::blocks
