#pragma once
// The unit cube of marching cubes: corner, edge and face numbering shared by the table generator, the
// mesher and the tests. The numbering is the one documented in include/isopatch/marching_cubes.hpp.

#include <array>

namespace isopatch::mc {

/// Integer coordinates (0 or 1) of corner i.
inline constexpr std::array<std::array<int, 3>, 8> kCorner = {{
    {0, 0, 0},
    {1, 0, 0},
    {1, 1, 0},
    {0, 1, 0},
    {0, 0, 1},
    {1, 0, 1},
    {1, 1, 1},
    {0, 1, 1},
}};

/// The two corners of edge e; the first has the smaller coordinate along the edge's axis.
inline constexpr std::array<std::array<int, 2>, 12> kEdge = {{
    {0, 1},
    {1, 2},
    {3, 2},
    {0, 3},
    {4, 5},
    {5, 6},
    {7, 6},
    {4, 7},
    {0, 4},
    {1, 5},
    {2, 6},
    {3, 7},
}};

/// A cube face: its corners in cyclic order, and its outward normal as (axis, sign).
struct CubeFace {
  std::array<int, 4> corners;
  int axis;
  int sign;
};

inline constexpr std::array<CubeFace, 6> kFace = {{
    {{0, 1, 2, 3}, 2, -1},
    {{4, 5, 6, 7}, 2, +1},
    {{0, 1, 5, 4}, 1, -1},
    {{3, 2, 6, 7}, 1, +1},
    {{0, 3, 7, 4}, 0, -1},
    {{1, 2, 6, 5}, 0, +1},
}};

/// The edge joining corners a and b, or -1 when they are not adjacent.
constexpr int edge_between(int a, int b) {
  for (int e = 0; e < 12; ++e)
    if ((kEdge[e][0] == a && kEdge[e][1] == b) || (kEdge[e][0] == b && kEdge[e][1] == a)) return e;
  return -1;
}

/// True when corner i is negative in the sign configuration `case_index`.
constexpr bool negative(int case_index, int corner) {
  return ((case_index >> corner) & 1) != 0;
}

/// True when edge e has one negative and one non-negative corner in `case_index`.
constexpr bool crossed(int case_index, int e) {
  return negative(case_index, kEdge[e][0]) != negative(case_index, kEdge[e][1]);
}

}  // namespace isopatch::mc
