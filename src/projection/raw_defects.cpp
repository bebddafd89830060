// Defects of the projection mesh by vertex role (raw_defects.hpp).
#include "projection/raw_defects.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <tbb/parallel_sort.h>

#include "core/triangle_angle.hpp"
#include "core/vertex_role.hpp"

namespace isopatch {
namespace {

/// The defect kind of a vertex role: 0 corner, 1 seam, 2 interior (centres too), 3 fan.
int kind_of(float role) {
  switch (static_cast<VertexRole>(static_cast<std::uint8_t>(role))) {
    case VertexRole::Corner:
      return 0;
    case VertexRole::Side:
      return 1;
    case VertexRole::Interior:
    case VertexRole::Centre:
    case VertexRole::Remeshed:  // the raw mesh has none; counted as interior
      return 2;
    case VertexRole::FanCentre:
      return 3;
  }
  return 2;
}

/// Rank of a kind when a triangle takes the most seam-like of its vertices: fan > corner > seam > interior.
int rank(int kind) {
  constexpr int kRank[RawDefects::kKinds] = {2, 1, 0, 3};
  return kRank[kind];
}

}  // namespace

RawDefects raw_defects(const Mesh& mesh, const std::vector<float>& roles, double size) {
  RawDefects d;
  const std::size_t n = mesh.positions.size();
  // Valence from the triangles; an edge seen once (a boundary edge) marks both ends as boundary.
  std::vector<std::uint32_t> valence(n, 0);
  std::vector<bool> boundary(n, false);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  tbb::parallel_sort(edges.begin(), edges.end());
  const double short_edge = size / 5.0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    const auto [a, b] = edges[i];
    ++valence[a], ++valence[b];
    if (j - i == 1) boundary[a] = boundary[b] = true;
    if ((mesh.positions[a] - mesh.positions[b]).norm() < short_edge) ++d.short_edges;
    i = j;
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (valence[v] == 0) continue;
    const int k = kind_of(roles[v]);
    ++d.vertices[k];
    if (!boundary[v] && valence[v] != 6) ++d.irregular_vertices[k];
  }
  const double cos20 = std::cos(20.0 * std::numbers::pi / 180.0),
               cos10 = std::cos(10.0 * std::numbers::pi / 180.0);
  for (const Triangle& t : mesh.triangles) {
    int k = kind_of(roles[t[0]]);
    for (std::size_t i = 1; i < 3; ++i)
      if (const int ki = kind_of(roles[t[i]]); rank(ki) > rank(k)) k = ki;
    ++d.triangles[k];
    const double cosine =
        smallest_angle_cosine(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    if (cosine > cos20) ++d.triangles_under_20[k];
    if (cosine > cos10) ++d.triangles_under_10[k];
  }
  return d;
}

}  // namespace isopatch
