// The interval cover of the places where two faces of a CSG shape may meet (csg/crease_cover.hpp).
#include <gtest/gtest.h>

#include <isopatch/expression.hpp>

#include <algorithm>
#include <cmath>

#include "csg/crease_cover.hpp"
#include "csg/crease_search.hpp"
#include "csg/face_set.hpp"

namespace isopatch {
namespace {

const Box kCoverBox{Vec3::Constant(-1.5), Vec3::Constant(1.5)};
constexpr const char* kCoverCube = "max(max(abs(x),abs(y)),abs(z))-1";

/// Distance from p to the nearest of the cube's twelve edges.
double to_cube_edge(const Vec3& p) {
  double best = 1e300;
  for (int a = 0; a < 3; ++a)  // edges along axis a
    for (const double s : {-1.0, 1.0})
      for (const double t : {-1.0, 1.0}) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const double along = std::clamp(p[a], -1.0, 1.0);
        Vec3 q;
        q[a] = along;
        q[b] = s;
        q[c] = t;
        best = std::min(best, (p - q).norm());
      }
  return best;
}

TEST(CreaseCover, TheCellsOfACubeHugItsTwelveEdgesAndHoldEveryPointOfThem) {
  FaceSet faces(parse_expression(kCoverCube), kCoverBox);
  const double leaf = 0.05;
  const CreaseCover cover = crease_cover(faces, kCoverBox, leaf, kCoverBudget);
  ASSERT_FALSE(cover.cells.empty());
  EXPECT_GT(cover.without_surface, 0u);
  EXPECT_GT(cover.one_face, 0u);
  EXPECT_EQ(cover.over_budget, 0u);
  for (const CreaseCell& c : cover.cells) {
    EXPECT_LE(c.box.size().maxCoeff(), leaf);
    EXPECT_FALSE(c.pairs.empty());
    for (const auto& [a, b] : c.pairs) EXPECT_LT(a, b);
    // Interval widths of a linear slab grow with the cell: the cells lie within a few of them.
    EXPECT_LT(to_cube_edge(c.box.centre()), 4.0 * leaf);
  }
  // Every point of every edge lies in a cell (the cover is sound: no crease can be outside it).
  for (int a = 0; a < 3; ++a)
    for (const double s : {-1.0, 1.0})
      for (const double t : {-1.0, 1.0})
        for (double u = -0.97; u < 1.0; u += 0.0611) {
          Vec3 p;
          p[a] = u;
          p[(a + 1) % 3] = s;
          p[(a + 2) % 3] = t;
          const bool inside = std::any_of(cover.cells.begin(), cover.cells.end(),
                                          [&](const CreaseCell& c) { return c.box.contains(p, 1e-12); });
          EXPECT_TRUE(inside) << p.transpose();
        }
}

TEST(CreaseCover, NoCellWhereNoSwitchChangesOnTheSurface) {
  // A sphere has no switch: nothing to cover.
  FaceSet sphere(parse_expression("x^2+y^2+z^2-1"), kCoverBox);
  EXPECT_TRUE(crease_cover(sphere, kCoverBox, 0.05, kCoverBudget).cells.empty());
  // Two spheres far apart: the min between them switches only where f cannot vanish.
  FaceSet apart(parse_expression("min(x^2+y^2+(z-0.8)^2-0.25,x^2+y^2+(z+0.8)^2-0.25)"), kCoverBox);
  const CreaseCover cover = crease_cover(apart, kCoverBox, 0.05, kCoverBudget);
  EXPECT_TRUE(cover.cells.empty());
  EXPECT_GT(cover.without_surface, 0u);
}

TEST(CreaseCover, ABudgetStopsTheExaminationAndCountsWhatIsLeft) {
  FaceSet faces(parse_expression(kCoverCube), kCoverBox);
  const CreaseCover cover = crease_cover(faces, kCoverBox, 0.05, 100);
  EXPECT_EQ(cover.examined, 100u);
  EXPECT_GT(cover.over_budget, 0u);
}

TEST(CreaseCover, TheSearchExplainsEveryCellOrCountsItUncertain) {
  // The cube's 12 edges explain every cell; with the cover cut short, what it did not examine is
  // uncertain, and a corner cut below the seed grid is found by the cover alone.
  const double cell = 3.0 / 64.0;
  FaceSet cube(parse_expression(kCoverCube), kCoverBox);
  const CreaseSearch full = find_creases(cube, kCoverBox, cell);
  EXPECT_EQ(full.graph.curves.size(), 12u);
  EXPECT_GT(full.certificate.cells, 0u);
  EXPECT_EQ(full.certificate.uncertain, 0u);
  FaceSet again(parse_expression(kCoverCube), kCoverBox);
  const CreaseSearch cut_short = find_creases(again, kCoverBox, cell, 50);
  EXPECT_EQ(cut_short.certificate.examined, 50u);
  EXPECT_GT(cut_short.certificate.uncertain, 0u);
  FaceSet corner(parse_expression("max(max(max(abs(x),abs(y)),abs(z))-1,x+y+z-2.98)"), kCoverBox);
  const CreaseSearch found = find_creases(corner, kCoverBox, cell);
  EXPECT_EQ(found.certificate.found, 3u);
  EXPECT_EQ(found.graph.curves.size(), 15u);
  EXPECT_EQ(found.certificate.uncertain, 0u);
}

}  // namespace
}  // namespace isopatch
