// analyze_shape_away (metrics.hpp): the element shape and valence with balls about given points left out.
#include <isopatch/error.hpp>
#include <isopatch/metrics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "analysis_meshes.hpp"

namespace isopatch {
namespace {

std::size_t triangles_at(const Mesh& m, std::uint32_t v) {
  return static_cast<std::size_t>(
      std::count_if(m.triangles.begin(), m.triangles.end(),
                    [&](const Triangle& t) { return t[0] == v || t[1] == v || t[2] == v; }));
}

TEST(ShapeAway, WithoutCentresItIsTheWholeMesh) {
  const Mesh m = test::icosphere(3);
  const ShapeAwayReport a = analyze_shape_away(m, {}, 0.1);
  EXPECT_EQ(a.triangles, m.triangle_count());
  EXPECT_EQ(a.triangles_near, 0u);
  EXPECT_DOUBLE_EQ(a.smallest_angle, count_small_angles(m, 20.0).smallest);
  EXPECT_DOUBLE_EQ(a.share_below_20, analyze_shape(m).share_below_20);
  const ValenceReport v = analyze_valence(m);
  EXPECT_EQ(a.interior_vertices, v.interior_vertices);
  EXPECT_DOUBLE_EQ(a.share_6, v.share_6);
}

TEST(ShapeAway, ABallAboutASliverLeavesItOut) {
  // Vertex 0 of the icosphere is one of its 12 of valence 5; pulled almost onto a neighbour, its five
  // triangles become slivers (and two of them almost degenerate).
  Mesh m = test::icosphere(3);
  ASSERT_EQ(triangles_at(m, 0), 5u);
  const Triangle& t = *std::find_if(m.triangles.begin(), m.triangles.end(), [](const Triangle& tri) {
    return tri[0] == 0 || tri[1] == 0 || tri[2] == 0;
  });
  const std::uint32_t neighbour = t[0] == 0 ? t[1] : t[0];
  m.positions[0] = m.positions[neighbour] + 0.02 * (m.positions[0] - m.positions[neighbour]);
  ASSERT_LT(analyze_shape(m).min_angle.min, 5.0);
  const std::vector<Vec3> centre{m.positions[0]};
  const ShapeAwayReport a = analyze_shape_away(m, centre, 1e-3);
  EXPECT_EQ(a.centres, 1u);
  EXPECT_EQ(a.triangles_near, 5u);  // only vertex 0 lies in the ball: its five triangles
  EXPECT_EQ(a.triangles, m.triangle_count() - 5u);
  EXPECT_GT(a.smallest_angle, 30.0);
  EXPECT_EQ(a.share_below_20, 0.0);
  // 642 vertices, 12 of valence 5 (on a closed mesh all interior): vertex 0 is left out of the share.
  const ValenceReport v = analyze_valence(m);
  ASSERT_EQ(v.interior_vertices, 642u);
  EXPECT_DOUBLE_EQ(v.share_6, 630.0 / 642.0);
  EXPECT_EQ(a.interior_vertices, 641u);
  EXPECT_DOUBLE_EQ(a.share_6, 630.0 / 641.0);
  // A radius reaching the neighbour takes its triangles too.
  const ShapeAwayReport wide = analyze_shape_away(m, centre, 0.05);
  EXPECT_GT(wide.triangles_near, a.triangles_near);
  EXPECT_EQ(wide.triangles + wide.triangles_near, m.triangle_count());
}

TEST(ShapeAway, BadInputIsAnInputError) {
  const Mesh m = test::icosphere(1);
  const std::vector<Vec3> centre{Vec3::Zero()};
  EXPECT_THROW(analyze_shape_away(m, centre, 0.0), InputError);
  EXPECT_THROW(analyze_shape_away(m, centre, std::numeric_limits<double>::quiet_NaN()), InputError);
  const std::vector<Vec3> bad{Vec3(std::numeric_limits<double>::infinity(), 0.0, 0.0)};
  EXPECT_THROW(analyze_shape_away(m, bad, 0.1), InputError);
}

}  // namespace
}  // namespace isopatch
