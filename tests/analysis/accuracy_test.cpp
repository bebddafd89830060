// Accuracy against f: first-order distance, triangle and vertex normal errors, curvature errors.
#include <isopatch/callable_surface.hpp>
#include <isopatch/metrics.hpp>

#include <gtest/gtest.h>

#include <cmath>

#include "analysis_meshes.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace {

TEST(Accuracy, VerticesOnTheSphereHaveZeroDistanceAndCentroidsTheChordalSag) {
  const Mesh m = test::icosphere(3);
  const AccuracyReport a = analyze_accuracy(m, *test::sphere());
  EXPECT_EQ(a.vertex_distance.count, m.vertex_count());
  EXPECT_EQ(a.centroid_distance.count, m.triangle_count());
  EXPECT_LT(a.vertex_distance.max, 1e-15);
  // d1 = (1 - c^2) / (2c) at a centroid of norm c; the largest sag belongs to the centroid closest to 0.
  double smallest = 1.0;
  for (const Triangle& t : m.triangles)
    smallest = std::min(smallest, ((m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0).norm());
  EXPECT_NEAR(a.centroid_distance.max, (1.0 - smallest * smallest) / (2.0 * smallest), 1e-15);
  EXPECT_NEAR(a.diagonal, 2.0 * std::sqrt(3.0), 0.2);  // the icosphere nearly fills [-1, 1]^3
  EXPECT_EQ(a.undefined_samples, 0u);
}

TEST(Accuracy, ScaledSphereHasTheFirstOrderDistance) {
  Mesh m = test::icosphere(2);
  for (Vec3& p : m.positions) p *= 1.01;
  const AccuracyReport a = analyze_accuracy(m, *test::sphere());
  const double d1 = (1.01 * 1.01 - 1.0) / (2.0 * 1.01);
  EXPECT_NEAR(a.vertex_distance.min, d1, 1e-14);
  EXPECT_NEAR(a.vertex_distance.max, d1, 1e-14);
  EXPECT_NEAR(a.vertex_distance.rms, d1, 1e-14);
}

TEST(Accuracy, NormalErrorsAreSmallOnAFineSphere) {
  const AccuracyReport a = analyze_accuracy(test::icosphere(4), *test::sphere());
  EXPECT_LT(a.vertex_normal_error.max, 0.2);  // symmetric fans: the area-weighted normal is nearly radial
  EXPECT_LT(a.triangle_normal_error.max, 1.0);
  EXPECT_GT(a.triangle_normal_error.mean, 0.0);
}

TEST(Accuracy, FlippedTriangleShowsAHalfTurn) {
  Mesh m = test::icosphere(3);
  std::swap(m.triangles[7][1], m.triangles[7][2]);
  const AccuracyReport a = analyze_accuracy(m, *test::sphere());
  EXPECT_GT(a.triangle_normal_error.max, 175.0);
  EXPECT_LT(a.triangle_normal_error.p99, 5.0);  // only one of 1280 triangles is wrong
  // Its vertices' normals tilt but stay on the right side: each fan has five or six triangles.
  EXPECT_LT(a.vertex_normal_error.max, 90.0);
}

TEST(Accuracy, CurvatureErrorOfAFineIcosphere) {
  const AccuracyReport a = analyze_accuracy(test::icosphere(5), *test::sphere());
  EXPECT_EQ(a.mean_curvature.vertices, 10242u);
  EXPECT_EQ(a.mean_curvature.undefined, 0u);
  EXPECT_LT(a.mean_curvature.nrms, 0.01);
  EXPECT_GT(a.mean_curvature.nrms, 0.0);
  EXPECT_LE(a.mean_curvature.abs_error.median, a.mean_curvature.abs_error.max);
  EXPECT_LT(a.gaussian_curvature.nrms, 0.05);
}

TEST(Accuracy, CurvatureOfAnOpenMeshUsesOnlyInteriorVertices) {
  Mesh m = test::icosphere(3);
  m.triangles.erase(m.triangles.begin(), m.triangles.begin() + 4);  // one level-0 face's first child
  const AccuracyReport a = analyze_accuracy(m, *test::sphere());
  const ValenceReport v = analyze_valence(m);
  EXPECT_EQ(a.mean_curvature.vertices + a.mean_curvature.undefined, v.interior_vertices);
  EXPECT_LT(v.interior_vertices, m.vertex_count());
}

TEST(Accuracy, SingularPointsAreCountedNotMixedIn) {
  // A mesh vertex at the centre of the sphere, where grad f = 0.
  Mesh m = test::hexagon_fan();
  const AccuracyReport a = analyze_accuracy(m, *test::sphere());
  EXPECT_EQ(a.vertex_distance.count, 6u);
  EXPECT_GE(a.undefined_samples, 1u);
  EXPECT_EQ(a.mean_curvature.vertices, 0u);
  EXPECT_EQ(a.mean_curvature.undefined, 1u);
  EXPECT_TRUE(std::isnan(a.mean_curvature.nrms));
}

TEST(Quality, CombinesAllReports) {
  const Mesh m = test::icosphere(2);
  const SurfacePtr s = test::sphere();
  const QualityReport q = analyze_quality(m, s.get());
  ASSERT_TRUE(q.accuracy.has_value());
  EXPECT_EQ(q.topology.genus, 0);
  EXPECT_EQ(q.valence.interior_vertices, 162u);
  EXPECT_EQ(q.shape.min_angle.count, 320u);
  EXPECT_LT(q.accuracy->vertex_distance.max, 1e-15);
}

}  // namespace
}  // namespace isopatch
