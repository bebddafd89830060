// The vertex and triangle numbering of the regular refinement (lattice_layout.hpp).
#include "refine/lattice_layout.hpp"

#include <isopatch/error.hpp>

#include <cassert>
#include <limits>
#include <string>

namespace isopatch::refine {

LatticeLayout::LatticeLayout(const Mesh& base, const BaseEdges& edges, int level)
    : base_(base), edges_(edges), k_(level) {
  assert(level >= 1 && level <= kMaxLevel);
  base_vertices_ = base.vertex_count();
  triangles_ = base.triangle_count();
  edge_start_ = base_vertices_;
  inner_start_ = edge_start_ + edges.size() * static_cast<std::size_t>(k_ - 1);
  inner_ = static_cast<std::size_t>((k_ - 1) * (k_ - 2) / 2);
  vertex_count_ = inner_start_ + triangles_ * inner_;
  if (vertex_count_ >= std::numeric_limits<std::uint32_t>::max())
    throw LimitError("the refined mesh would have " + std::to_string(vertex_count_) +
                         " vertices, more than 32-bit vertex numbers hold",
                     "max_vertices");
}

std::uint32_t LatticeLayout::vertex(std::size_t t, int i, int j) const {
  const Triangle& tri = base_.triangles[t];
  const int w = k_ - i - j;  // weight of corner 0, in k-ths
  if (i == 0 && j == 0) return tri[0];
  if (w == 0 && j == 0) return tri[1];
  if (w == 0 && i == 0) return tri[2];
  // Which side (from corner s to corner s + 1) the point lies on, and how far along it, in k-ths.
  int side = -1, along = 0;
  if (j == 0) {
    side = 0;  // corner 0 -> 1
    along = i;
  } else if (w == 0) {
    side = 1;  // corner 1 -> 2
    along = j;
  } else if (i == 0) {
    side = 2;  // corner 2 -> 0
    along = w;
  }
  if (side < 0) return static_cast<std::uint32_t>(inner_start(t) + inner_index(i, j));
  const std::uint32_t e = edges_.of_triangle[t][static_cast<std::size_t>(side)];
  const bool forward = edges_.ends[e][0] == tri[static_cast<std::size_t>(side)];
  return edge_point(e, forward ? along : k_ - along);
}

void LatticeLayout::emit_triangles(std::size_t t, Triangle* out) const {
  std::size_t n = 0;
  for (int j = 0; j < k_; ++j)
    for (int i = 0; i + j < k_; ++i) {
      out[n++] = {vertex(t, i, j), vertex(t, i + 1, j), vertex(t, i, j + 1)};
      if (i + j + 2 <= k_) out[n++] = {vertex(t, i + 1, j), vertex(t, i + 1, j + 1), vertex(t, i, j + 1)};
    }
  assert(n == static_cast<std::size_t>(k_ * k_));
}

}  // namespace isopatch::refine
