// The pieces of a base (piece_map.hpp).
#include "refine/piece_map.hpp"

#include <isopatch/error.hpp>

#include <limits>
#include <span>

namespace isopatch::refine {

PieceMap map_pieces(const Mesh& base, const BaseEdges& edges, const RefinePieces& pieces, int level) {
  constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();
  PieceMap map;
  map.vertex_piece.assign(base.vertex_count(), kUnset);
  map.edge_piece.assign(edges.size(), kUnset);
  map.joins_pieces.assign(edges.size(), 0);
  for (std::size_t t = 0; t < base.triangle_count(); ++t) {
    const std::uint32_t piece = pieces.triangle_piece.empty() ? 0 : pieces.triangle_piece[t];
    for (int s = 0; s < 3; ++s) {
      const std::uint32_t v = base.triangles[t][static_cast<std::size_t>(s)];
      if (map.vertex_piece[v] == kUnset) map.vertex_piece[v] = piece;
      const std::uint32_t e = edges.of_triangle[t][static_cast<std::size_t>(s)];
      if (map.edge_piece[e] == kUnset)
        map.edge_piece[e] = piece;
      else if (map.edge_piece[e] != piece)
        map.joins_pieces[e] = 1;
    }
  }
  for (std::uint32_t& p : map.vertex_piece)
    if (p == kUnset) p = 0;
  if (!pieces.vertex_piece.empty()) map.vertex_piece = pieces.vertex_piece;

  map.curve_first.assign(edges.size(), -1);
  map.on_curve.assign(base.vertex_count(), 0);
  if (pieces.curve_points) {
    std::vector<Vec3> points(static_cast<std::size_t>(level - 1));
    for (std::uint32_t e = 0; e < edges.size(); ++e) {
      const auto [a, b] = edges.ends[e];
      if (!pieces.curve_points(a, b, level, std::span<Vec3>(points))) continue;
      for (const Vec3& p : points)
        if (!p.allFinite()) throw InputError("refine: a curve point of a base edge is not finite");
      map.curve_first[e] = static_cast<std::int64_t>(map.curve_points.size());
      map.curve_points.insert(map.curve_points.end(), points.begin(), points.end());
      map.on_curve[a] = map.on_curve[b] = 1;
    }
  }
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    if (map.on_curve_edge(e)) map.joins_pieces[e] = 0;
    map.joining_edges += map.joins_pieces[e];
  }
  return map;
}

}  // namespace isopatch::refine
