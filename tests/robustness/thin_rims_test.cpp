// Rims thinner than an edge (issue 35): flat ellipsoids whose rim turns within one edge length. The
// curvature search must find the rim (and nothing on gently curved surfaces), the graded size field
// must give the exact lower envelope of its sources, and the default mesh must follow the rim.
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "api/curvature_feature_sizes.hpp"
#include "api/graded_sizes.hpp"
#include "api/size_estimate.hpp"

namespace isopatch {
namespace {

TEST(GradedSizes, ExactLowerEnvelopeOfItsSources) {
  std::mt19937 random(35);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0), size(0.001, 0.2);
  std::vector<SizeSource> sources;
  for (int i = 0; i < 3000; ++i) {
    // Sources along a curve, where the tree prunes most, and a few scattered.
    const double t = coordinate(random) * 3.0;
    const Vec3 p = i % 10 == 0 ? Vec3(coordinate(random), coordinate(random), coordinate(random))
                               : Vec3(std::cos(t), std::sin(t), 0.05 * t);
    // Every seventh with a gentler grading of its own (as a rim's sources), the others the field's.
    sources.push_back({p, size(random), i % 7 == 0 ? 0.1 : 0.0});
  }
  const GradedSizes field(sources, 0.15, 0.3);
  for (int q = 0; q < 500; ++q) {
    const Vec3 p(1.5 * coordinate(random), 1.5 * coordinate(random), 1.5 * coordinate(random));
    double expected = 0.15;
    for (const SizeSource& s : sources)
      expected = std::min(expected, s.size + (s.grading > 0.0 ? s.grading : 0.3) * (p - s.point).norm());
    ASSERT_DOUBLE_EQ(field.at(p), expected) << "at " << p.transpose();
  }
  EXPECT_EQ(field.source_count(),
            static_cast<std::size_t>(std::count_if(sources.begin(), sources.end(),
                                                   [](const SizeSource& s) { return s.size < 0.15; })));
  EXPECT_DOUBLE_EQ(GradedSizes({}, 0.15, 0.3).at(Vec3::Zero()), 0.15);
}

TEST(CurvatureFeatureSizes, FindsTheRimOfAFlatEllipsoidOnly) {
  // Semi-axes 4, 1, 0.1: the rim's radius of curvature is c^2 / a = 0.0025 at x = +-4, 0.01 at y = +-1.
  const Box box{Vec3::Constant(-4.2), Vec3::Constant(4.2)};
  const SurfacePtr ellipsoid = resolve_surface("x^2/16+y^2+z^2/0.01-1", box);
  const double edge = 8.4 / 64;
  const CurvatureFeatureSearch found = curvature_feature_sources(*ellipsoid, box, edge, edge / 512);
  ASSERT_TRUE(found.searched);
  ASSERT_FALSE(found.sources.empty());
  double smallest = edge;
  for (const SizeSource& s : found.sources) {
    smallest = std::min(smallest, s.size);
    EXPECT_LT(s.size, 0.5 * edge);
    EXPECT_NEAR(ellipsoid->value(s.point), 0.0, 1e-6);
    // On the rim: where the ellipse x^2/16 + y^2 = 1 of the equator is, within the flat sheet's height.
    EXPECT_LT(std::abs(s.point.z()), 0.06);
    EXPECT_GT(s.point.x() * s.point.x() / 16 + s.point.y() * s.point.y(), 0.8);
  }
  const double turn = CurvatureFeatureParams{}.turn;  // radians per edge at the tip
  EXPECT_LT(smallest, turn * 0.0025 * 1.2);
  EXPECT_GT(smallest, turn * 0.0025 * 0.8);
  for (const SizeSource& s : found.sources) EXPECT_EQ(s.grading, CurvatureFeatureParams{}.grading);
  // The same for any number of threads.
  {
    tbb::task_arena one(1);
    const CurvatureFeatureSearch serial =
        one.execute([&] { return curvature_feature_sources(*ellipsoid, box, edge, edge / 512); });
    ASSERT_EQ(serial.sources.size(), found.sources.size());
    for (std::size_t i = 0; i < serial.sources.size(); ++i) {
      EXPECT_EQ(serial.sources[i].point, found.sources[i].point);
      EXPECT_EQ(serial.sources[i].size, found.sources[i].size);
    }
  }
  // A sphere of radius 1 at the same edge turns 0.13 radians per edge: nothing to refine.
  const SurfacePtr sphere = resolve_surface("x^2+y^2+z^2-1", box);
  EXPECT_TRUE(curvature_feature_sources(*sphere, box, edge, edge / 512).sources.empty());
}

TEST(ThinRims, DefaultMeshFollowsTheRimAndUniformDoesNot) {
  // Semi-axes 4, 1, 0.2: rim radius 0.01, a thirteenth of the default edge (0.131). One size gives 1,934
  // vertices, 24.9 degrees but H nRMS 0.50 (one row of triangles across the rim); the rim sizes 21,390
  // vertices, 25.0 degrees, H nRMS 0.033.
  const Box box{Vec3::Constant(-4.2), Vec3::Constant(4.2)};
  const SurfacePtr surface = resolve_surface("x^2/16+y^2+z^2/0.04-1", box);
  Settings s;
  s.box = box;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*surface, s, &stats);
  ASSERT_TRUE(stats.local_sizes.has_value());
  EXPECT_GT(stats.local_sizes->curvature_sources, 0u);
  EXPECT_GT(stats.local_sizes->added_vertices, 0u);
  EXPECT_LT(stats.local_sizes->extent.hi.z(), 0.2);
  const QualityReport q = analyze_quality(mesh, surface.get());
  ASSERT_TRUE(q.accuracy.has_value());
  EXPECT_GE(q.shape.min_angle.min, 20.0);
  EXPECT_GE(q.valence.share_6, 0.9);
  EXPECT_LE(q.accuracy->mean_curvature.nrms, 0.1);
  // One size spans the rim with a single row of triangles: the curvature there is lost (H nRMS 0.5).
  s.uniform = true;
  const Mesh uniform = mesh_surface(*surface, s);
  EXPECT_GT(analyze_quality(uniform, surface.get()).accuracy->mean_curvature.nrms,
            3.0 * q.accuracy->mean_curvature.nrms);
}

TEST(ThinRims, ASurfaceThinnerThanTheEstimateGridIsNotRefused) {
  // The estimate's 32-cell grid has one cell across this flat box: no grid edge changes sign. The
  // estimate says so instead of refusing, and the mesher finds the surface.
  const Box box{Vec3(-4.2, -1.1, -0.12), Vec3(4.2, 1.1, 0.12)};
  const SurfacePtr surface = resolve_surface("x^2/16+y^2+z^2/0.01-1", box);
  Settings s;
  s.box = box;
  const SizeEstimate estimate = estimate_size(*surface, s, box, true);
  EXPECT_FALSE(estimate.found);
  EXPECT_EQ(estimate.vertices, 0.0);
  // A box with no surface at all is still refused, by the mesher.
  Settings empty;
  empty.box = Box{Vec3::Constant(2.0), Vec3::Constant(3.0)};
  EXPECT_THROW(mesh_surface(*resolve_surface("x^2+y^2+z^2-1", *empty.box), empty), NoSurfaceError);
}

}  // namespace
}  // namespace isopatch
