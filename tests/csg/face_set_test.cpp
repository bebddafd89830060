// Faces of a CSG shape by branch, merged where they meet smoothly (csg/face_set.hpp).
#include <gtest/gtest.h>

#include <isopatch/expression.hpp>

#include <array>
#include <set>
#include <utility>
#include <vector>

#include "csg/face_set.hpp"

namespace isopatch {
namespace {

const Box kFaceBox{Vec3::Constant(-2.0), Vec3::Constant(2.0)};

TEST(FaceSet, TheFacesOfACubeAreItsSixPlanes) {
  FaceSet faces(parse_expression("max(max(abs(x),abs(y)),abs(z))-1"), kFaceBox);
  ASSERT_TRUE(faces.has_switches());
  std::set<int> ids;
  for (int a = 0; a < 3; ++a)
    for (const double s : {-1.0, 1.0}) {
      Vec3 p(0.2, -0.3, 0.1);
      p[a] = s;
      const int id = faces.face_at(p);
      ids.insert(id);
      // The face's function is the plane s x_a - 1 everywhere.
      const Vec3 far(3.0, -4.0, 5.0);
      EXPECT_DOUBLE_EQ(faces.function(id)->value(far), s * far[a] - 1.0);
      EXPECT_EQ(faces.boundary_face(std::array{id}, p, 1e-12), -1);
    }
  EXPECT_EQ(ids.size(), 6u);
}

TEST(FaceSet, AcrossARegionsEndIsTheNeighbouringFace) {
  FaceSet faces(parse_expression("max(max(abs(x),abs(y)),abs(z))-1"), kFaceBox);
  const int x_face = faces.face_at({1.0, 0.2, 0.3});
  const int y_face = faces.face_at({0.2, 1.0, 0.3});
  // On the plane x = 1 beyond the edge y = 1 the face y = 1 takes over.
  EXPECT_EQ(faces.boundary_face(std::array{x_face}, {1.0, 1.2, 0.3}, 1e-9), y_face);
  EXPECT_EQ(faces.boundary_face(std::array{x_face}, {1.0, 0.5, 0.3}, 1e-9), -1);
  // Both faces hold on their edge; past its end the face z = 1 takes over from the first that fails.
  EXPECT_EQ(faces.boundary_face(std::array{x_face, y_face}, {1.0, 1.0, 0.3}, 1e-9), -1);
  EXPECT_EQ(faces.boundary_face(std::array{x_face, y_face}, {1.0, 1.0, 1.2}, 1e-9),
            faces.face_at({0.2, 0.3, 1.0}));
}

TEST(FaceSet, MergedFacesKeepOnlyTheSwitchesTheyDisagreeOnOpen) {
  // Two coplanar faces from two boxes: merged, their function is the plane (no switch of either box).
  FaceSet faces(parse_expression("min(max(abs(x),abs(y))-1,max(abs(x-1.5),abs(y))-1)"), kFaceBox);
  const int a = faces.face_at({0.0, 1.0, 0.0});
  const int b = faces.face_at({2.2, 1.0, 0.0});
  ASSERT_NE(a, b);
  faces.merge(a, b);
  EXPECT_EQ(faces.root(b), faces.root(a));
  const SurfacePtr& f = faces.function(a);
  for (const Vec3& p : {Vec3(-5.0, 0.3, 1.0), Vec3(7.0, 2.0, -3.0)})
    EXPECT_DOUBLE_EQ(f->value(p), p.y() - 1.0);
  EXPECT_THROW(faces.merge(a, faces.face_at({0.0, -1.0, 0.0})), Error);
}

TEST(FaceSet, TheRegionBoundIsZeroOnTheFaceAndNegativeBeyondIt) {
  FaceSet faces(parse_expression("max(max(abs(x),abs(y)),abs(z))-1"), kFaceBox);
  const int x_face = faces.face_at({1.0, 0.2, 0.3});
  const SurfacePtr bound = faces.region_bound(x_face);
  EXPECT_EQ(bound->value({1.0, 0.2, 0.3}), 0.0);
  // Beyond the edge y = 1 by 0.1 along the face: minus about 0.1.
  EXPECT_NEAR(bound->value({1.0, 1.1, 0.3}), -0.1, 1e-12);
  const SurfacePtr plane = plane_surface(Vec3::UnitZ(), 0.5, kFaceBox);
  EXPECT_DOUBLE_EQ(plane->value({3.0, 1.0, 2.0}), 1.5);
}

TEST(FaceSet, TheFacesAcrossASwitchAreItsTwoSides) {
  FaceSet faces(parse_expression("max(max(abs(x),abs(y)),abs(z))-1"), kFaceBox);
  // Switch 3 in tape order is the max of |x| and |y| (abs x, abs y, max, abs z, max): at a point of the
  // edge x = y = 1 its sides are the faces x = 1 and y = 1.
  const std::array<int, 1> inner{2};
  const auto [a, b] = faces.faces_across(inner, {1.0, 1.0, 0.3}).at(0);
  EXPECT_EQ((std::set<int>{a, b}),
            (std::set<int>{faces.face_at({1.0, 0.2, 0.3}), faces.face_at({0.2, 1.0, 0.3})}));
  // The outer max at a point of the face z = 1: z = 1 against the face the inner max takes there.
  const std::array<int, 2> both{2, 4};
  const std::vector<std::pair<int, int>> sides = faces.faces_across(both, {0.5, 0.2, 1.0});
  ASSERT_EQ(sides.size(), 2U);
  const auto [c, d] = sides[1];
  EXPECT_EQ((std::set<int>{c, d}),
            (std::set<int>{faces.face_at({0.5, 0.2, 1.0}), faces.face_at({1.0, 0.2, 0.5})}));
  // The inner max is not a crease there: both its sides are the face z = 1.
  EXPECT_EQ(sides[0].first, sides[0].second);
}

}  // namespace
}  // namespace isopatch
