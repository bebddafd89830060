// Newton projection onto f = 0, free and inside a coordinate plane.
#include <gtest/gtest.h>

#include <cmath>

#include "surface/project_point.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace {

TEST(ProjectPoint, LandsOnTheSphereAlongTheNormal) {
  const SurfacePtr s = test::sphere();
  const Sampler f(*s);
  Vec3 p(0.3, 0.4, 0.5), gradient;
  ASSERT_TRUE(project_to_surface(f, p, 1e-14, 1.0, &gradient));
  EXPECT_NEAR(p.norm(), 1.0, 1e-13);
  EXPECT_NEAR(p.normalized().dot(Vec3(0.3, 0.4, 0.5).normalized()), 1.0, 1e-12);  // radial move
  EXPECT_NEAR(gradient.normalized().dot(p), 1.0, 1e-12);
}

TEST(ProjectPoint, InAPlaneKeepsTheFrozenCoordinateExactly) {
  const SurfacePtr s = test::sphere();
  const Sampler f(*s);
  // Plane z = 0.5 meets the unit sphere in the circle of radius sqrt(0.75).
  Vec3 p(0.2, -0.1, 0.5), gradient;
  ASSERT_TRUE(project_to_surface_in_plane(f, p, 2, 1e-14, 1.0, &gradient));
  EXPECT_EQ(p.z(), 0.5);
  EXPECT_NEAR(std::hypot(p.x(), p.y()), std::sqrt(0.75), 1e-13);
  EXPECT_NEAR(std::atan2(p.y(), p.x()), std::atan2(-0.1, 0.2), 1e-12);  // moved within the plane, radially
  EXPECT_NEAR(gradient.normalized().dot(p), 1.0, 1e-12);                // the full gradient is returned
}

TEST(ProjectPoint, InAPlaneParallelToTheSurfaceFails) {
  // f = x - 0.25 has no gradient inside the planes x = const: nothing to follow.
  const SurfacePtr s = make_surface([](auto x, auto, auto) { return x - 0.25; },
                                    Box{Vec3::Constant(-1), Vec3::Constant(1)}, "slab");
  const Sampler f(*s);
  Vec3 p(0.5, 0.1, 0.2);
  EXPECT_FALSE(project_to_surface_in_plane(f, p, 0, 1e-14, 1.0));
  Vec3 q(0.5, 0.1, 0.2);
  EXPECT_TRUE(project_to_surface(f, q, 1e-14, 1.0));
  EXPECT_NEAR(q.x(), 0.25, 1e-15);
}

}  // namespace
}  // namespace isopatch
