#pragma once
/// \file face_cycles.hpp
/// The boundary cycles of the faces of a CSG shape: the graph's curves walked with each face on the
/// left (seen from outside), turning at every node to the next curve of that face clockwise from the
/// one it came along (the faces of an embedded graph, as in a half-edge structure). Curves are split
/// where they turn by more than a quarter turn, closed loops into three or more, so that every cycle
/// becomes a polygon a multi-sided patch can span. docs/creases.md.

#include <cstddef>
#include <vector>

#include "csg/crease_graph.hpp"
#include "csg/face_set.hpp"

namespace isopatch {

/// A curve traversed with `face` on its left: forward when the face is the curve's left, reversed when
/// it is its right.
struct HalfCurve {
  int curve = 0;
  bool reversed = false;
};

/// One boundary cycle of a face.
struct FaceCycle {
  int face = -1;
  std::vector<HalfCurve> sides;  ///< side k ends at the node where side k + 1 starts
};

/// Every cycle of every face of the graph, in curve order.
/// \throw CreaseError when the curves at a node do not pair up (the shape is not a 2-manifold there).
std::vector<FaceCycle> face_cycles(const CreaseGraph& graph, FaceSet& faces);

/// The node a half-curve starts and ends at.
int start_node(const CreaseGraph& graph, const HalfCurve& h);
int end_node(const CreaseGraph& graph, const HalfCurve& h);
/// The points of a half-curve in its direction.
std::vector<Vec3> half_points(const CreaseGraph& graph, const HalfCurve& h);

/// Splits curve `c` at its dense point `index` (0 < index < size - 1): the curve keeps the part up to
/// the new node, a new curve (appended) takes the rest. Returns the new node.
int split_curve(CreaseGraph& graph, std::size_t c, std::size_t index);

/// Splits every curve that turns by more than a quarter turn into equal parts that turn by less, and
/// every closed loop into at least three; then, while a cycle has fewer than three sides, its longest
/// side in two. Returns the cycles after the splits.
std::vector<FaceCycle> split_into_polygons(CreaseGraph& graph, FaceSet& faces);

}  // namespace isopatch
