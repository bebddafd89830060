#include <gtest/gtest.h>

#include "project/ray_march.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace {

TEST(RayMarch, FindsTheFirstCrossingInsideTheRegion) {
  const auto s = test::sphere(1.0);
  const Sampler f(*s);
  const Box region{Vec3::Constant(-2), Vec3::Constant(2)};
  // From the centre (inside) along +x: the crossing at x = 1.
  const auto hit = march_to_surface(f, Vec3::Zero(), f.value(Vec3::Zero()), Vec3(1, 0, 0), region);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x(), 1.0, 1e-12);
  // From outside, the direction (towards the positive side) is reversed: from (1.5,0,0) with +x, go -x.
  const Vec3 out(1.5, 0, 0);
  const auto back = march_to_surface(f, out, f.value(out), Vec3(1, 0, 0), region);
  ASSERT_TRUE(back);
  EXPECT_NEAR(back->point.x(), 1.0, 1e-12);
  EXPECT_LT(back->ray_direction.x(), 0.0);
}

TEST(RayMarch, MissesWhenTheRegionEndsFirst) {
  const auto s = test::sphere(1.0);
  const Sampler f(*s);
  const Box region{Vec3::Constant(-0.5), Vec3::Constant(0.5)};
  EXPECT_FALSE(march_to_surface(f, Vec3::Zero(), f.value(Vec3::Zero()), Vec3(1, 0, 0), region));
}

TEST(RayMarch, ExitDistanceOfSlabs) {
  const Box box{Vec3::Zero(), Vec3::Ones()};
  EXPECT_DOUBLE_EQ(exit_distance(Vec3(0.25, 0.5, 0.5), Vec3(1, 0, 0), box), 0.75);
  EXPECT_DOUBLE_EQ(exit_distance(Vec3(0.25, 0.5, 0.5), Vec3(-1, 0, 0), box), 0.25);
}

}  // namespace
}  // namespace isopatch
