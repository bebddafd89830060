// Vertices near defects (defect_region.hpp).
#include "remesh/defect_region.hpp"

#include "core/triangle_angle.hpp"
#include "remesh/valence_flips.hpp"

namespace isopatch {

std::vector<std::uint32_t> vertices_near_defects(const EditableMesh& mesh, const SizeField& sizes,
                                                 const DefectThresholds& thresholds, int rings) {
  std::vector<char> marked(mesh.vertex_slots(), 0);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!mesh.triangle_alive[t]) continue;
    const Triangle& tri = mesh.triangles[t];
    bool bad = smallest_angle_cosine(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]) >
               thresholds.cos_small_angle;
    for (std::size_t i = 0; i < 3 && !bad; ++i) {
      const std::uint32_t a = tri[i], b = tri[(i + 1) % 3];
      const double l = (mesh.positions[a] - mesh.positions[b]).norm(), h = sizes.edge(a, b);
      bad = l > thresholds.split_factor * h || l < thresholds.collapse_factor * h;
    }
    if (bad)
      for (std::uint32_t v : tri) marked[v] = 1;
  }
  for (std::uint32_t v = 0; v < mesh.vertex_slots(); ++v)
    if (mesh.alive(v) && static_cast<int>(mesh.valence(v)) != target_valence(mesh, v)) marked[v] = 1;
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<char> grown = marked;
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
      if (!mesh.triangle_alive[t]) continue;
      const Triangle& tri = mesh.triangles[t];
      if (marked[tri[0]] || marked[tri[1]] || marked[tri[2]])
        for (std::uint32_t v : tri) grown[v] = 1;
    }
    marked.swap(grown);
  }
  std::vector<std::uint32_t> list;
  for (std::uint32_t v = 0; v < marked.size(); ++v)
    if (marked[v] && mesh.alive(v)) list.push_back(v);
  return list;
}

}  // namespace isopatch
