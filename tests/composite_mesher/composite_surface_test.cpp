// CompositeSurface: the function of the patch whose region holds the point most deeply.
#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <cmath>

#include "composite_model/composite_surface.hpp"
#include "test_composites.hpp"

namespace isopatch {
namespace {

TEST(CompositeSurface, PicksThePatchWhoseRegionHoldsThePointMostDeeply) {
  const auto c = test::octahedron_sphere();
  const CompositeSurface s(c);
  // Octant (+,+,+) is face 0, (-,+,+) face 1 (test_composites.hpp).
  EXPECT_EQ(s.patch_at(Vec3(0.5, 0.4, 0.3)), 0u);
  EXPECT_EQ(s.patch_at(Vec3(-0.5, 0.4, 0.3)), 1u);
  EXPECT_GT(s.region_depth(0, Vec3(0.5, 0.4, 0.3)), 0.0);
  EXPECT_LT(s.region_depth(1, Vec3(0.5, 0.4, 0.3)), 0.0);
  for (const Vec3& p : {Vec3(0.3, -0.7, 0.2), Vec3(-0.1, -0.2, -0.9), Vec3(1.1, 0.3, -0.4)}) {
    EXPECT_NEAR(s.value(p), (p.squaredNorm() - 1.0) / 2.0, 1e-15);
    EXPECT_NEAR((s.value_gradient(p).gradient - p).norm(), 0.0, 1e-15);
    EXPECT_NEAR((s.second_order(p).hessian - Mat3::Identity()).norm(), 0.0, 1e-15);
  }
  EXPECT_EQ(s.name(), c->name);
}

TEST(CompositeSurface, RefusesEmptyComposites) {
  EXPECT_THROW(CompositeSurface(nullptr), InputError);
  auto c = std::make_shared<Composite>();
  c->box = Box{Vec3::Constant(-1), Vec3::Constant(1)};
  EXPECT_THROW(CompositeSurface{c}, InputError);
  c = test::octahedron_sphere();
  c->patches[0].surface = nullptr;
  EXPECT_THROW(CompositeSurface{c}, InputError);
  c = test::octahedron_sphere();
  c->box = Box{Vec3::Constant(1), Vec3::Constant(-1)};
  EXPECT_THROW(CompositeSurface{c}, InputError);
}

}  // namespace
}  // namespace isopatch
