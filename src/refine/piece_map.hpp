#pragma once
// Which function each part of a base made of pieces lies on (refine_mesh.hpp, refine_pieces): the piece
// of every base vertex and base edge, the edges on curves the pieces meet along with the curve's points
// on them, and the edges that join two pieces off any curve (which the refinement cannot place).

#include <isopatch/geometry.hpp>

#include <cstdint>
#include <vector>

#include "refine/base_edges.hpp"
#include "refine/refine_mesh.hpp"

namespace isopatch::refine {

struct PieceMap {
  /// Per base vertex and per base edge: the piece of the lowest-numbered triangle that uses it (0 for a
  /// vertex no triangle uses); per vertex RefinePieces::vertex_piece instead when given.
  std::vector<std::uint32_t> vertex_piece;
  std::vector<std::uint32_t> edge_piece;
  /// Per base edge: the index in curve_points of its k - 1 points, or -1 for an edge off the curves.
  std::vector<std::int64_t> curve_first;
  std::vector<Vec3> curve_points;
  /// Per base vertex: 1 when it ends an edge on a curve (a corner or a curve sample: held in place).
  std::vector<std::uint8_t> on_curve;
  /// Per base edge: 1 when its two triangles lie on different pieces but it is not on a curve.
  std::vector<std::uint8_t> joins_pieces;
  std::size_t joining_edges = 0;

  bool on_curve_edge(std::uint32_t e) const { return curve_first[e] >= 0; }
};

/// The map of `base` (whose edges are `edges`) refined by `level`.
/// \pre pieces.triangle_piece is empty (every triangle on piece 0) or one entry per base triangle, each
///      below pieces.functions.size(); pieces.vertex_piece likewise per base vertex.
/// \throw InputError when pieces.curve_points returns points that are not finite.
PieceMap map_pieces(const Mesh& base, const BaseEdges& edges, const RefinePieces& pieces, int level);

}  // namespace isopatch::refine
