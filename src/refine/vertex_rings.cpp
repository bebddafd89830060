// Compressed one-rings (vertex_rings.hpp): a counting pass and a filling pass, in triangle order.
#include "refine/vertex_rings.hpp"

namespace isopatch::refine {

VertexRings::VertexRings(std::size_t vertex_count, std::span<const Triangle> triangles)
    : offsets_(vertex_count + 1, 0) {
  for (const Triangle& t : triangles)
    for (std::uint32_t v : t) ++offsets_[v + 1];
  for (std::size_t v = 0; v < vertex_count; ++v) offsets_[v + 1] += offsets_[v];
  neighbours_.resize(offsets_[vertex_count]);
  std::vector<std::uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
  for (const Triangle& t : triangles)
    for (int c = 0; c < 3; ++c)
      neighbours_[fill[t[static_cast<std::size_t>(c)]]++] = t[static_cast<std::size_t>((c + 1) % 3)];
}

}  // namespace isopatch::refine
