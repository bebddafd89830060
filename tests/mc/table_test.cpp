// The generated marching cubes table, checked case by case against the properties that make the
// mesher watertight, manifold and outward oriented.
#include <isopatch/marching_cubes.hpp>

#include "core/cube_numbering.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace isopatch {
namespace {

using cube::kCorner;
using cube::kEdge;
using cube::kFace;

Vec3 corner_point(int c) {
  return Vec3(kCorner[c][0], kCorner[c][1], kCorner[c][2]);
}
Vec3 midpoint(int e) {
  return 0.5 * (corner_point(kEdge[e][0]) + corner_point(kEdge[e][1]));
}

// From the negative to the non-negative end of a crossed edge.
Vec3 negative_to_positive(int case_index, int e) {
  const int a = kEdge[e][0], b = kEdge[e][1];
  return cube::negative(case_index, a) ? corner_point(b) - corner_point(a)
                                       : corner_point(a) - corner_point(b);
}

bool on_face(int e, int f) {
  const auto& c = kFace[f];
  return std::count(c.begin(), c.end(), kEdge[e][0]) == 1 && std::count(c.begin(), c.end(), kEdge[e][1]) == 1;
}

// Directed triangle edges of a case, as (from cube edge, to cube edge) -> count.
std::map<std::pair<int, int>, int> directed_edges(const McCase& c) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : c.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  return edges;
}

// The directed boundary segments of a case lying on face f.
std::set<std::pair<int, int>> face_segments(int case_index, int f) {
  const auto edges = directed_edges(marching_cubes_table()[case_index]);
  std::set<std::pair<int, int>> segments;
  for (const auto& [e, count] : edges)
    if (edges.count({e.second, e.first}) == 0 && on_face(e.first, f) && on_face(e.second, f))
      segments.insert(e);
  return segments;
}

// Connected components of the triangles of a case (sharing a cube edge), as lists of triangles.
std::vector<std::vector<std::array<int, 3>>> patches(const McCase& c) {
  std::vector<int> label(c.triangles.size(), -1);
  int count = 0;
  for (std::size_t s = 0; s < c.triangles.size(); ++s) {
    if (label[s] >= 0) continue;
    std::vector<std::size_t> stack = {s};
    label[s] = count;
    while (!stack.empty()) {
      const auto t = c.triangles[stack.back()];
      stack.pop_back();
      for (std::size_t u = 0; u < c.triangles.size(); ++u)
        if (label[u] < 0 && std::any_of(t.begin(), t.end(), [&](int e) {
              return std::find(c.triangles[u].begin(), c.triangles[u].end(), e) != c.triangles[u].end();
            })) {
          label[u] = count;
          stack.push_back(u);
        }
    }
    ++count;
  }
  std::vector<std::vector<std::array<int, 3>>> result(count);
  for (std::size_t t = 0; t < c.triangles.size(); ++t) result[label[t]].push_back(c.triangles[t]);
  return result;
}

// Components of the corners of one sign; positive corners also connect across face diagonals (the
// ambiguity rule keeps them joined), negative ones only along cube edges.
int sign_components(int case_index, bool negative_side) {
  std::array<int, 8> label{};
  label.fill(-1);
  int count = 0;
  auto same = [&](int c) { return cube::negative(case_index, c) == negative_side; };
  auto linked = [&](int a, int b) {
    if (cube::edge_between(a, b) >= 0) return true;
    if (negative_side) return false;
    for (const auto& corners : kFace)
      for (int k = 0; k < 2; ++k)
        if ((corners[k] == a && corners[k + 2] == b) || (corners[k] == b && corners[k + 2] == a)) return true;
    return false;
  };
  for (int s = 0; s < 8; ++s) {
    if (!same(s) || label[s] >= 0) continue;
    std::vector<int> stack = {s};
    label[s] = count;
    while (!stack.empty()) {
      const int a = stack.back();
      stack.pop_back();
      for (int b = 0; b < 8; ++b)
        if (same(b) && label[b] < 0 && linked(a, b)) {
          label[b] = count;
          stack.push_back(b);
        }
    }
    ++count;
  }
  return count;
}

TEST(McTable, EmptyExactlyForUniformCases) {
  const auto& table = marching_cubes_table();
  EXPECT_TRUE(table[0].triangles.empty());
  EXPECT_TRUE(table[255].triangles.empty());
  for (int c = 1; c < 255; ++c) EXPECT_FALSE(table[c].triangles.empty()) << "case " << c;
  EXPECT_EQ(&table, &marching_cubes_table());  // built once
}

TEST(McTable, VerticesAreExactlyTheCrossedEdges) {
  for (int c = 0; c < 256; ++c) {
    std::set<int> used;
    for (const auto& t : marching_cubes_table()[c].triangles) {
      EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) << "case " << c;
      for (int e : t) {
        ASSERT_TRUE(e >= 0 && e < 12);
        EXPECT_TRUE(cube::crossed(c, e)) << "case " << c << " uses uncrossed edge " << e;
        used.insert(e);
      }
    }
    for (int e = 0; e < 12; ++e)
      EXPECT_EQ(used.count(e), cube::crossed(c, e) ? 1u : 0u) << "case " << c << " edge " << e;
  }
}

TEST(McTable, EachCaseIsAnOrientedSurfaceBoundedOnTheCubeFaces) {
  for (int c = 0; c < 256; ++c) {
    for (const auto& [e, count] : directed_edges(marching_cubes_table()[c])) {
      EXPECT_EQ(count, 1) << "case " << c << ": edge traversed twice the same way";
      if (directed_edges(marching_cubes_table()[c]).count({e.second, e.first}) != 0) continue;
      bool on_some_face = false;
      for (int f = 0; f < 6; ++f)
        on_some_face = on_some_face || (on_face(e.first, f) && on_face(e.second, f));
      EXPECT_TRUE(on_some_face) << "case " << c << ": boundary edge " << e.first << "-" << e.second
                                << " inside the cube";
    }
  }
}

TEST(McTable, EachPatchIsADiskAndTheRegionsFormATree) {
  for (int c = 1; c < 255; ++c) {
    const auto parts = patches(marching_cubes_table()[c]);
    for (const auto& part : parts) {
      std::set<int> vertices;
      std::set<std::pair<int, int>> edges;
      for (const auto& t : part)
        for (int k = 0; k < 3; ++k) {
          vertices.insert(t[k]);
          edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
        }
      const long euler = static_cast<long>(vertices.size()) - static_cast<long>(edges.size()) +
                         static_cast<long>(part.size());
      EXPECT_EQ(euler, 1) << "case " << c;
    }
    // Disks cut the cube into the sign regions; regions and disks form a tree.
    const int regions = sign_components(c, true) + sign_components(c, false);
    EXPECT_EQ(static_cast<int>(parts.size()), regions - 1) << "case " << c;
  }
}

TEST(McTable, NormalsPointFromNegativeToPositive) {
  // Each patch (on edge midpoints) faces the way its crossed edges run from negative to positive,
  // and no triangle of it is folded back against the patch's mean normal.
  for (int c = 1; c < 255; ++c)
    for (const auto& part : patches(marching_cubes_table()[c])) {
      std::set<int> edges;
      for (const auto& t : part) edges.insert(t.begin(), t.end());
      Vec3 across = Vec3::Zero();
      for (int e : edges) across += negative_to_positive(c, e);
      Vec3 area = Vec3::Zero();
      for (const auto& t : part)
        area += (midpoint(t[1]) - midpoint(t[0])).cross(midpoint(t[2]) - midpoint(t[0]));
      EXPECT_GT(area.dot(across), 0.0) << "case " << c;
      for (const auto& t : part) {
        const Vec3 normal = (midpoint(t[1]) - midpoint(t[0])).cross(midpoint(t[2]) - midpoint(t[0]));
        EXPECT_GT(normal.dot(area), 0.0) << "case " << c;
      }
    }
}

TEST(McTable, NeighboursAgreeOnEverySharedFace) {
  // The cube across face f sees the same four corners on its opposite face f'. Whatever its other
  // corners are, it must put the same segments there, traversed the other way.
  for (int f = 0; f < 6; ++f) {
    const int axis = cube::kFaceAxis[f];
    const auto& face = kFace[f];
    const auto& opposite = kFace[f ^ 1];
    ASSERT_EQ(cube::kFaceAxis[f ^ 1], axis);
    ASSERT_NE(cube::kFaceSide[f ^ 1], cube::kFaceSide[f]);
    // Corner of `face` -> corner of the neighbour (same position, moved across the axis).
    std::array<int, 8> across{};
    across.fill(-1);
    for (int c : face)
      for (int d : opposite) {
        bool same = true;
        for (int a = 0; a < 3; ++a)
          if (a != axis && kCorner[c][a] != kCorner[d][a]) same = false;
        if (same) across[c] = d;
      }
    auto edge_across = [&](int e) { return cube::edge_between(across[kEdge[e][0]], across[kEdge[e][1]]); };
    for (int c = 0; c < 256; ++c) {
      std::set<std::pair<int, int>> expected;
      for (const auto& [a, b] : face_segments(c, f)) expected.insert({edge_across(b), edge_across(a)});
      for (int others = 0; others < 16; ++others) {
        int neighbour = 0;
        for (int c0 : face)
          if (cube::negative(c, c0)) neighbour |= 1 << across[c0];
        for (int k = 0; k < 4; ++k)
          if ((others >> k) & 1) neighbour |= 1 << face[k];  // its far corners sit where face is
        EXPECT_EQ(face_segments(neighbour, f ^ 1), expected) << "face " << f << " case " << c;
      }
    }
  }
}

TEST(McTable, ComplementReversesUnambiguousFaces) {
  for (int c = 0; c < 256; ++c)
    for (int f = 0; f < 6; ++f) {
      int crossed = 0;
      for (int e : cube::kFaceEdge[f])
        if (cube::crossed(c, e)) ++crossed;
      if (crossed == 4) continue;  // ambiguous: the rule separates the negative corners, not symmetric
      std::set<std::pair<int, int>> reversed;
      for (const auto& [a, b] : face_segments(c, f)) reversed.insert({b, a});
      EXPECT_EQ(face_segments(255 ^ c, f), reversed) << "case " << c;
    }
}

TEST(McTable, OneCornerCaseIsOneTriangle) {
  for (int corner = 0; corner < 8; ++corner) {
    EXPECT_EQ(marching_cubes_table()[1 << corner].triangles.size(), 1u);
    EXPECT_EQ(marching_cubes_table()[255 ^ (1 << corner)].triangles.size(), 1u);
  }
  // Two negative corners on a face diagonal stay apart: two triangles, not a quad.
  EXPECT_EQ(marching_cubes_table()[(1 << 0) | (1 << 2)].triangles.size(), 2u);
  EXPECT_EQ(patches(marching_cubes_table()[(1 << 0) | (1 << 2)]).size(), 2u);
  // Its complement joins the two positive corners through the face: one band of four triangles.
  EXPECT_EQ(patches(marching_cubes_table()[255 ^ ((1 << 0) | (1 << 2))]).size(), 1u);
}

TEST(McTable, AFlatSquareIsCutFromCornerZerosVerticalEdge) {
  // Cases 15 and 240 cross the four vertical edges: a planar square, where both diagonals are equally
  // good. The loop starts at the vertical edge of corner 0 (the table's loop order), so both triangles
  // share that edge and the edge of the opposite corner 2.
  const int from_corner_0 = cube::edge_between(0, 4), from_corner_2 = cube::edge_between(2, 6);
  for (const int c : {15, 240}) {
    const McCase& square = marching_cubes_table()[c];
    ASSERT_EQ(square.triangles.size(), 2u) << c;
    for (const auto& t : square.triangles) {
      EXPECT_EQ(std::count(t.begin(), t.end(), from_corner_0), 1) << c;
      EXPECT_EQ(std::count(t.begin(), t.end(), from_corner_2), 1) << c;
    }
  }
}

}  // namespace
}  // namespace isopatch
