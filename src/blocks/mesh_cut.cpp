// The cut of a tile's mesh (mesh_cut.hpp).
#include "blocks/mesh_cut.hpp"

namespace isopatch::blocks {

std::unordered_map<std::uint64_t, std::uint32_t> directed_edges(const Mesh& mesh,
                                                                const std::vector<std::uint8_t>* kept) {
  std::unordered_map<std::uint64_t, std::uint32_t> count;
  count.reserve(3 * mesh.triangle_count());
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (kept && !(*kept)[t]) continue;
    const Triangle& tri = mesh.triangles[t];
    ++count[edge_key(tri[0], tri[1])];
    ++count[edge_key(tri[1], tri[2])];
    ++count[edge_key(tri[2], tri[0])];
  }
  return count;
}

std::vector<std::uint8_t> cut_vertices(const Mesh& mesh) {
  const auto count = directed_edges(mesh);
  std::vector<std::uint8_t> cut(mesh.vertex_count(), 0);
  for (const Triangle& t : mesh.triangles)
    for (std::size_t c = 0; c < 3; ++c) {
      const std::uint32_t a = t[c], b = t[(c + 1) % 3];
      if (!count.count(edge_key(b, a))) cut[a] = cut[b] = 1;
    }
  return cut;
}

}  // namespace isopatch::blocks
