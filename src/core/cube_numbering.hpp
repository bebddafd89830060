#pragma once
/// \file cube_numbering.hpp
/// The one numbering of the corners, edges and faces of a cube, shared by Marching Cubes (its generated
/// case table and its mesher) and the octree partition (cells, configuration table, loops), as in
/// docs/algorithms.md 2.3 (the numbering of salvipeter/marching-surface). Edges run around the faces
/// z=0 and z=1 as cycles, then the vertical edges; faces keep the order z=0, z=1, x=1, x=0, y=0, y=1 and
/// list their corners counter-clockwise as seen from outside the cube, which loop orientation needs.
/// A sign configuration (case index) is the 8-bit code with bit i set when corner i is negative.

#include <array>

namespace isopatch::cube {

/// Offset of corner i from the cube's lower corner, in cube sizes (each coordinate 0 or 1).
inline constexpr std::array<std::array<int, 3>, 8> kCorner = {
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};

/// Edge e joins corners kEdge[e][0] and kEdge[e][1] (not ordered by coordinate: see edge_lower_corner).
inline constexpr std::array<std::array<int, 2>, 12> kEdge = {
    {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {1, 5}, {6, 2}, {0, 4}, {7, 3}}};

/// Face f: its corners, counter-clockwise seen from outside the cube.
inline constexpr std::array<std::array<int, 4>, 6> kFace = {
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {1, 2, 6, 5}, {0, 4, 7, 3}, {0, 1, 5, 4}, {3, 7, 6, 2}}};

/// Axis (0 = x, 1 = y, 2 = z) of the normal of face f; faces f and f ^ 1 are opposite.
inline constexpr std::array<int, 6> kFaceAxis = {2, 2, 0, 0, 1, 1};

/// 0 when face f lies in the lower plane of its axis, 1 in the upper one.
inline constexpr std::array<int, 6> kFaceSide = {0, 1, 1, 0, 0, 1};

/// The sign (-1 or +1) of the outward normal of face f along kFaceAxis[f].
constexpr int face_outward_sign(int f) {
  return kFaceSide[f] == 1 ? 1 : -1;
}

/// The edge joining corners a and b, or -1 when they are not adjacent.
constexpr int edge_between(int a, int b) {
  for (int e = 0; e < 12; ++e)
    if ((kEdge[e][0] == a && kEdge[e][1] == b) || (kEdge[e][0] == b && kEdge[e][1] == a)) return e;
  return -1;
}

/// The axis along which edge e runs.
constexpr int edge_axis(int e) {
  for (int a = 0; a < 3; ++a)
    if (kCorner[kEdge[e][0]][a] != kCorner[kEdge[e][1]][a]) return a;
  return -1;
}

/// The endpoint of edge e with the smaller coordinate along the edge.
constexpr int edge_lower_corner(int e) {
  const int a = edge_axis(e);
  return kCorner[kEdge[e][0]][a] < kCorner[kEdge[e][1]][a] ? kEdge[e][0] : kEdge[e][1];
}

/// kFaceEdge[f][k]: the edge from kFace[f][k] to kFace[f][(k + 1) % 4].
inline constexpr std::array<std::array<int, 4>, 6> kFaceEdge = [] {
  std::array<std::array<int, 4>, 6> table{};
  for (int f = 0; f < 6; ++f)
    for (int k = 0; k < 4; ++k) table[f][k] = edge_between(kFace[f][k], kFace[f][(k + 1) % 4]);
  return table;
}();

/// True when corner i is negative in the sign configuration `case_index`.
constexpr bool negative(int case_index, int corner) {
  return ((case_index >> corner) & 1) != 0;
}

/// True when edge e has one negative and one non-negative corner in `case_index`.
constexpr bool crossed(int case_index, int e) {
  return negative(case_index, kEdge[e][0]) != negative(case_index, kEdge[e][1]);
}

}  // namespace isopatch::cube
