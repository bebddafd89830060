// The generated configuration table (docs/algorithms.md 2.5) and the face-by-face linking it rests on.
#include "partition/config_table.hpp"

#include "core/cube_numbering.hpp"
#include "partition/cube_cycles.hpp"

#include <isopatch/geometry.hpp>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <map>
#include <set>
#include <utility>

namespace isopatch {
namespace {

Vec3 corner_position(int i) {
  const auto& o = cube::kCorner[i];
  return Vec3(o[0], o[1], o[2]);
}

Vec3 edge_midpoint(int e) {
  return 0.5 * (corner_position(cube::kEdge[e][0]) + corner_position(cube::kEdge[e][1]));
}

TEST(CubeNumbering, FacesAreCounterClockwiseFromOutside) {
  for (int f = 0; f < 6; ++f) {
    Vec3 outward = Vec3::Zero();
    outward[cube::kFaceAxis[f]] = cube::face_outward_sign(f);
    Vec3 newell = Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      const Vec3 p = corner_position(cube::kFace[f][k]);
      EXPECT_EQ(p[cube::kFaceAxis[f]], cube::kFaceSide[f]) << "face " << f;
      newell += p.cross(corner_position(cube::kFace[f][(k + 1) % 4]));
    }
    EXPECT_GT(newell.dot(outward), 0.0) << "face " << f;
    for (int k = 0; k < 4; ++k) EXPECT_GE(cube::kFaceEdge[f][k], 0) << "face " << f;
    EXPECT_EQ(cube::kFaceAxis[f ^ 1], cube::kFaceAxis[f]) << "face " << f;  // f ^ 1 is the opposite face
    EXPECT_NE(cube::kFaceSide[f ^ 1], cube::kFaceSide[f]) << "face " << f;
  }
}

TEST(CubeNumbering, EdgesJoinNeighbourCornersAlongOneAxis) {
  for (int e = 0; e < 12; ++e) {
    const int axis = cube::edge_axis(e);
    ASSERT_GE(axis, 0) << "edge " << e;
    EXPECT_EQ(cube::edge_between(cube::kEdge[e][0], cube::kEdge[e][1]), e);
    EXPECT_EQ(cube::kCorner[cube::edge_lower_corner(e)][axis], 0) << "edge " << e;
    for (int a = 0; a < 3; ++a) {
      if (a == axis) continue;
      EXPECT_EQ(cube::kCorner[cube::kEdge[e][0]][a], cube::kCorner[cube::kEdge[e][1]][a]) << "edge " << e;
    }
  }
  EXPECT_EQ(cube::edge_between(0, 6), -1);
  const int case_index = (1 << 0) | (1 << 4);  // corners 0 and 4 negative: edge 10 (0-4) is not crossed
  EXPECT_TRUE(cube::negative(case_index, 4));
  EXPECT_FALSE(cube::negative(case_index, 5));
  EXPECT_FALSE(cube::crossed(case_index, 10));
  EXPECT_TRUE(cube::crossed(case_index, 0));
}

TEST(ConfigTable, CountsMatchTheEnumeration) {
  const auto& table = config_table();
  std::map<ConfigClass, int> classes;
  std::map<int, int> single_sizes;
  for (int code = 0; code < 256; ++code) {
    const ConfigEntry& entry = table[code];
    ++classes[entry.kind];
    if (entry.kind == ConfigClass::SingleLoop) ++single_sizes[entry.loop_size];
    if (entry.kind == ConfigClass::SeveralLoops) {
      EXPECT_EQ(entry.loops, 2) << code;
      EXPECT_EQ(entry.loop_size, 3) << code;
    }
    // Complement symmetry: swapping inside and outside keeps the class.
    EXPECT_EQ(entry.kind, table[255 - code].kind) << code;
  }
  EXPECT_EQ(classes[ConfigClass::Empty], 2);
  EXPECT_EQ(classes[ConfigClass::SingleLoop], 126);
  EXPECT_EQ(classes[ConfigClass::SeveralLoops], 8);
  EXPECT_EQ(classes[ConfigClass::Ambiguous], 120);
  EXPECT_EQ(single_sizes[3], 16);
  EXPECT_EQ(single_sizes[4], 30);
  EXPECT_EQ(single_sizes[5], 48);
  EXPECT_EQ(single_sizes[6], 32);
  // The two cases the marching-surface table gets wrong (docs/algorithms.md 2.5).
  EXPECT_EQ(table[0b10100101].kind, ConfigClass::Ambiguous);
  EXPECT_EQ(table[0b00011011].kind, ConfigClass::SingleLoop);
  EXPECT_EQ(table[0b00011011].loop_size, 6);
}

TEST(CubeCycles, EveryCrossedEdgeOnceAndSidesOnTheirFaces) {
  for (int code = 0; code < 256; ++code) {
    for (int centre = 0; centre < 64; ++centre) {
      const auto negative = static_cast<std::uint8_t>(code);
      const auto cycles = cube_cycles(negative, static_cast<std::uint8_t>(centre));
      const std::uint16_t crossed = crossed_edges(negative);
      std::uint16_t seen = 0;
      for (const CubeCycle& cycle : cycles) {
        ASSERT_EQ(cycle.edges.size(), cycle.faces.size());
        ASSERT_GE(cycle.edges.size(), 3u);
        for (std::size_t k = 0; k < cycle.edges.size(); ++k) {
          const int e = cycle.edges[k];
          EXPECT_TRUE((crossed >> e) & 1u);
          EXPECT_FALSE((seen >> e) & 1u) << "edge twice, code " << code;
          seen = static_cast<std::uint16_t>(seen | (1u << e));
          const auto& fe = cube::kFaceEdge[cycle.faces[k]];
          const int next = cycle.edges[(k + 1) % cycle.edges.size()];
          EXPECT_NE(std::find(fe.begin(), fe.end(), e), fe.end());
          EXPECT_NE(std::find(fe.begin(), fe.end(), next), fe.end());
        }
      }
      EXPECT_EQ(seen, crossed) << "code " << code;
    }
  }
}

// Directed sides (edge pair) that cube_cycles puts on face f.
std::set<std::pair<int, int>> sides_on_face(std::uint8_t negative, std::uint8_t centre, int f) {
  std::set<std::pair<int, int>> sides;
  for (const CubeCycle& cycle : cube_cycles(negative, centre))
    for (std::size_t k = 0; k < cycle.edges.size(); ++k)
      if (cycle.faces[k] == f) sides.insert({cycle.edges[k], cycle.edges[(k + 1) % cycle.edges.size()]});
  return sides;
}

int corner_at(const std::array<int, 3>& offset) {
  for (int i = 0; i < 8; ++i)
    if (cube::kCorner[i] == offset) return i;
  return -1;
}

// Two cells sharing a face, with the same signs on it and the same centre sample, traverse every
// shared side in opposite directions, whatever their other corners: the watertight-orientation
// property at the level of the combinatorics.
TEST(CubeCycles, NeighboursTraverseSharedSidesInOppositeDirections) {
  for (int f = 0; f < 6; ++f) {
    const int axis = cube::kFaceAxis[f];
    int g = 0;  // the neighbour's face across f
    while (!(cube::kFaceAxis[g] == axis && cube::kFaceSide[g] != cube::kFaceSide[f])) ++g;
    std::array<int, 8> across{};  // corner of the neighbour matching corner i of f (or -1)
    across.fill(-1);
    for (int i : cube::kFace[f]) {
      auto o = cube::kCorner[i];
      o[axis] = 1 - o[axis];
      across[i] = corner_at(o);
    }
    auto edge_across = [&](int e) {
      return cube::edge_between(across[cube::kEdge[e][0]], across[cube::kEdge[e][1]]);
    };
    for (int code = 0; code < 256; ++code) {
      for (int rest = 0; rest < 16; ++rest) {
        int other = 0;
        int r = 0;
        for (int i = 0; i < 8; ++i) {
          const bool on_g =
              std::find(cube::kFace[g].begin(), cube::kFace[g].end(), i) != cube::kFace[g].end();
          if (!on_g) other |= ((rest >> r++) & 1) << i;
        }
        for (int i : cube::kFace[f]) other |= ((code >> i) & 1) << across[i];
        for (int centre = 0; centre < 2; ++centre) {
          const auto mine =
              sides_on_face(static_cast<std::uint8_t>(code), static_cast<std::uint8_t>(centre << f), f);
          const auto theirs =
              sides_on_face(static_cast<std::uint8_t>(other), static_cast<std::uint8_t>(centre << g), g);
          ASSERT_EQ(mine.size(), theirs.size()) << "face " << f << " code " << code;
          for (const auto& [a, b] : mine)
            EXPECT_TRUE(theirs.count({edge_across(b), edge_across(a)})) << "face " << f << " code " << code;
        }
      }
    }
  }
}

// With crossings at edge midpoints, every single loop is counter-clockwise about the direction from
// the negative corners to the positive ones (the stand-in for the gradient).
TEST(CubeCycles, SingleLoopsTurnAboutTheGradient) {
  for (int code = 1; code < 255; ++code) {
    if (config_table()[code].kind != ConfigClass::SingleLoop) continue;
    Vec3 negative_mean = Vec3::Zero();
    Vec3 positive_mean = Vec3::Zero();
    const int count = std::popcount(static_cast<unsigned>(code));
    for (int i = 0; i < 8; ++i) ((code >> i) & 1 ? negative_mean : positive_mean) += corner_position(i);
    const Vec3 gradient = positive_mean / (8 - count) - negative_mean / count;
    const auto cycles = cube_cycles(static_cast<std::uint8_t>(code), 0);
    ASSERT_EQ(cycles.size(), 1u);
    Vec3 newell = Vec3::Zero();
    const auto& edges = cycles[0].edges;
    for (std::size_t k = 0; k < edges.size(); ++k)
      newell += edge_midpoint(edges[k]).cross(edge_midpoint(edges[(k + 1) % edges.size()]));
    EXPECT_GT(newell.dot(gradient), 0.0) << "code " << code;
  }
}

}  // namespace
}  // namespace isopatch
