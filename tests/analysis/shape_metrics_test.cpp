// Element shape, valence and summary statistics on meshes whose values are known by hand.
#include <isopatch/error.hpp>
#include <isopatch/metrics.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "analysis_meshes.hpp"

namespace isopatch {
namespace {

Mesh single_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  Mesh m;
  m.positions = {a, b, c};
  m.triangles = {{0, 1, 2}};
  return m;
}

TEST(Summarize, HandComputedPercentilesMeanAndRms) {
  const Distribution d = summarize({5.0, 1.0, 4.0, 2.0, 3.0});
  EXPECT_EQ(d.count, 5u);
  EXPECT_DOUBLE_EQ(d.min, 1.0);
  EXPECT_DOUBLE_EQ(d.max, 5.0);
  EXPECT_DOUBLE_EQ(d.p5, 1.2);  // rank 0.05 * 4 = 0.2
  EXPECT_DOUBLE_EQ(d.p95, 4.8);
  EXPECT_DOUBLE_EQ(d.median, 3.0);
  EXPECT_DOUBLE_EQ(d.mean, 3.0);
  EXPECT_DOUBLE_EQ(d.rms, std::sqrt(11.0));  // (1 + 4 + 9 + 16 + 25) / 5
}

TEST(Summarize, EmptyIsNaNAndNaNSampleThrows) {
  const Distribution d = summarize({});
  EXPECT_EQ(d.count, 0u);
  EXPECT_TRUE(std::isnan(d.median));
  EXPECT_THROW(summarize({1.0, std::numeric_limits<double>::quiet_NaN()}), InputError);
}

TEST(Summarize, KeepsInfinities) {
  const double inf = std::numeric_limits<double>::infinity();
  const Distribution d = summarize({1.0, inf, inf});
  EXPECT_EQ(d.max, inf);
  EXPECT_EQ(d.p99, inf);
  EXPECT_EQ(d.mean, inf);
}

TEST(Shape, EquilateralTriangleIsPerfect) {
  const ShapeReport s =
      analyze_shape(single_triangle(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, std::sqrt(3.0), 0)));
  EXPECT_NEAR(s.min_angle.min, 60.0, 1e-12);
  EXPECT_NEAR(s.aspect_ratio.max, 1.0, 1e-12);
  EXPECT_NEAR(s.quality.min, 1.0, 1e-12);
  EXPECT_NEAR(s.edge_length.mean, 2.0, 1e-12);
  EXPECT_NEAR(s.edge_length_cv, 0.0, 1e-12);
  EXPECT_EQ(s.share_below_30, 0.0);
}

TEST(Shape, RightIsoscelesTriangleMatchesFormulas) {
  const ShapeReport s = analyze_shape(single_triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)));
  const double sqrt2 = std::sqrt(2.0);
  EXPECT_NEAR(s.min_angle.min, 45.0, 1e-12);
  // R = sqrt2 / 2, r = A / p = (1/2) / ((2 + sqrt2) / 2): R / (2r) = (1 + sqrt2) / 2.
  EXPECT_NEAR(s.aspect_ratio.max, (1.0 + sqrt2) / 2.0, 1e-12);
  // Q = (6 / sqrt3) (1/2) / (p sqrt2).
  EXPECT_NEAR(s.quality.min, 6.0 / std::sqrt(3.0) * 0.5 / ((2.0 + sqrt2) / 2.0 * sqrt2), 1e-12);
  // Lengths 1, 1, sqrt2: mean m = (2 + sqrt2) / 3, population std from the squared deviations.
  const double m = (2.0 + sqrt2) / 3.0;
  const double sd = std::sqrt((2 * (1 - m) * (1 - m) + (sqrt2 - m) * (sqrt2 - m)) / 3.0);
  EXPECT_NEAR(s.edge_length_cv, sd / m, 1e-12);
}

TEST(Shape, ThinAndDegenerateTrianglesAreCountedBelowThresholds) {
  Mesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.05, 0),           Vec3(2, 0, 0),
                 Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0.5, std::sqrt(0.75), 1)};
  m.triangles = {{0, 1, 2}, {0, 1, 3}, {4, 5, 6}};  // thin (about 5.7 deg), collinear, equilateral
  const ShapeReport s = analyze_shape(m);
  EXPECT_EQ(s.min_angle.min, 0.0);
  EXPECT_EQ(s.aspect_ratio.max, std::numeric_limits<double>::infinity());
  EXPECT_EQ(s.quality.min, 0.0);
  EXPECT_NEAR(s.min_angle.median, std::atan(0.1) * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(s.share_below_10, 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(s.share_below_30, 2.0 / 3.0, 1e-15);
  // The one-pass count agrees with the report.
  const SmallAngleCount small = count_small_angles(m, 10.0);
  EXPECT_EQ(small.triangles, 2u);
  EXPECT_EQ(small.smallest, 0.0);
  EXPECT_EQ(count_small_angles(m, 5.0).triangles, 1u);
  EXPECT_EQ(count_small_angles(m, 60.5).triangles, 3u);
  EXPECT_EQ(count_small_angles(Mesh{}, 10.0).smallest, 180.0);
}

TEST(Shape, IcosahedronIsEquilateralEverywhere) {
  const ShapeReport s = analyze_shape(test::icosahedron());
  EXPECT_EQ(s.min_angle.count, 20u);
  EXPECT_NEAR(s.min_angle.min, 60.0, 1e-9);
  EXPECT_NEAR(s.min_angle.max, 60.0, 1e-9);
  EXPECT_NEAR(s.quality.min, 1.0, 1e-12);
  EXPECT_EQ(s.edge_length.count, 30u);
  EXPECT_NEAR(s.edge_length.min, 2.0, 1e-12);
  EXPECT_NEAR(s.edge_length_cv, 0.0, 1e-12);
}

TEST(Valence, IcosahedronHasValenceFiveEverywhereAndGenusZero) {
  const QualityReport q = analyze_quality(test::icosahedron());
  EXPECT_EQ(q.topology.genus, 0);
  EXPECT_TRUE(q.topology.watertight());
  EXPECT_TRUE(q.topology.outward_oriented());
  EXPECT_EQ(q.valence.interior_vertices, 12u);
  EXPECT_EQ(q.valence.other_vertices, 0u);
  ASSERT_EQ(q.valence.histogram.size(), 6u);
  EXPECT_EQ(q.valence.histogram[5], 12u);
  EXPECT_EQ(q.valence.share_6, 0.0);
  EXPECT_EQ(q.valence.share_5_to_7, 1.0);
  EXPECT_FALSE(q.accuracy.has_value());
}

TEST(Valence, SubdividedIcosahedronHasTwelveFivesAndSixesElsewhere) {
  const Mesh m = test::icosphere(2);  // V = 10 * 4^2 + 2 = 162
  const ValenceReport v = analyze_valence(m);
  EXPECT_EQ(v.interior_vertices, 162u);
  EXPECT_EQ(v.histogram[5], 12u);
  EXPECT_EQ(v.histogram[6], 150u);
  EXPECT_DOUBLE_EQ(v.share_6, 150.0 / 162.0);
}

TEST(Valence, BoundaryVerticesOfAHoleAreLeftOut) {
  Mesh m = test::icosphere(2);
  const Triangle removed = m.triangles.back();
  m.triangles.pop_back();
  const ValenceReport v = analyze_valence(m);
  EXPECT_EQ(v.interior_vertices, 159u);
  EXPECT_EQ(v.other_vertices, 3u);
  // The three boundary vertices lost no neighbour, so the histogram of the others is unchanged
  // except for those three (each of valence 5 or 6 in the closed mesh).
  std::size_t boundary_fives = 0;
  for (std::uint32_t i : removed) boundary_fives += i < 12 ? 1 : 0;  // the icosahedron's own vertices
  EXPECT_EQ(v.histogram[5], 12u - boundary_fives);
  EXPECT_EQ(v.histogram[6], 150u - (3u - boundary_fives));
}

TEST(Valence, FlatFanCountsOnlyItsCentre) {
  const ValenceReport v = analyze_valence(test::hexagon_fan());
  EXPECT_EQ(v.interior_vertices, 1u);
  EXPECT_EQ(v.other_vertices, 6u);
  EXPECT_EQ(v.histogram[6], 1u);
  EXPECT_EQ(v.share_6, 1.0);
}

TEST(Valence, UnreferencedVerticesAreNeither) {
  Mesh m = test::hexagon_fan();
  m.positions.emplace_back(5, 5, 5);
  const ValenceReport v = analyze_valence(m);
  EXPECT_EQ(v.interior_vertices + v.other_vertices, 7u);
}

TEST(Metrics, RejectBadInput) {
  Mesh m = test::hexagon_fan();
  m.triangles.push_back({0, 1, 99});
  EXPECT_THROW(analyze_shape(m), InputError);
  EXPECT_THROW(analyze_quality(m), InputError);
  Mesh n = test::hexagon_fan();
  n.positions[3].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(analyze_valence(n), InputError);
}

}  // namespace
}  // namespace isopatch
