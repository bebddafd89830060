// The I-patch function: the sphere-octant identity, interpolation of the ribbons (G1), the rule A
// weights, the normalized and plain forms, exact derivatives against differences, the 0/0 guard, and
// the quadric pieces' interval bounds.
#include "composite_model/ipatch_surface.hpp"
#include "composite_model/quadric.hpp"

#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

namespace isopatch {
namespace {

const Box kBox{Vec3::Constant(-3.0), Vec3::Constant(3.0)};

SurfacePtr surface(const Quadric& q) {
  return std::make_shared<QuadricSurface>("piece", kBox, q);
}

/// The sphere octant of Sipos et al.'s tests: ribbons the cylinders (x^2+y^2-1)/2, (y^2+z^2-1)/2,
/// (z^2+x^2-1)/2, bounds z, x, y.
struct Octant {
  std::vector<SurfacePtr> ribbons, bounds;
  Octant() {
    const Vec3 axes[3] = {Vec3::UnitZ(), Vec3::UnitX(), Vec3::UnitY()};
    for (const Vec3& axis : axes) {
      ribbons.push_back(surface(ball_cylinder(Vec3::Zero(), axis, 1.0)));
      bounds.push_back(surface(Quadric::from(plane_through(Vec3::Zero(), axis))));
    }
  }
  IPatchSurface patch(const Vec3& centre) const {
    return IPatchSurface("octant", kBox, ribbons, bounds,
                         rule_a_weights(ribbons, bounds, centre, {}, "octant"));
  }
};

Vec3 random_in_octant(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.05, 1.5);
  return {u(rng), u(rng), u(rng)};
}

TEST(IPatchSurface, SphereOctantIdentityHoldsWithItsWeights) {
  const Octant o;
  const Vec3 c = Vec3::Constant(1.0 / std::sqrt(3.0));
  const IPatchSurface f = o.patch(c);
  for (double w : f.weights().w) EXPECT_NEAR(w, 2.0, 1e-12);
  EXPECT_NEAR(f.weights().w0, 3.0, 1e-15);
  std::mt19937 rng(1);
  double worst = 0.0, worst_grad = 0.0, worst_hessian = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 x = random_in_octant(rng);
    const SecondOrder s = f.second_order(x);
    worst = std::max(worst, std::abs(s.value - 0.5 * (x.squaredNorm() - 1.0)));
    worst_grad = std::max(worst_grad, (s.gradient - x).norm());
    worst_hessian = std::max(worst_hessian, (s.hessian - Mat3::Identity()).norm());
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(worst_grad, 1e-11);
  EXPECT_LT(worst_hessian, 1e-9);
}

TEST(IPatchSurface, InterpolatesItsRibbonsWithG1OnTheBoundaryCurves) {
  // An octant through an off-diagonal point: no longer the sphere, but still on every ribbon along its
  // boundary quarter circles, with the ribbon's normal.
  const Octant o;
  const IPatchSurface f = o.patch(Vec3(0.5, 0.7, 0.45));
  const Vec3 axes[3] = {Vec3::UnitZ(), Vec3::UnitX(), Vec3::UnitY()};
  for (int side = 0; side < 3; ++side) {
    const Vec3 a = axes[(side + 1) % 3], b = axes[(side + 2) % 3];  // the quarter circle in the plane B = 0
    for (int j = 1; j < 20; ++j) {
      const double t = M_PI / 2 * j / 20.0;
      const Vec3 x = std::cos(t) * a + std::sin(t) * b;
      EXPECT_LT(std::abs(o.ribbons[side]->value(x)), 1e-15);
      EXPECT_LT(std::abs(o.bounds[side]->value(x)), 1e-15);
      const ValueGradient g = f.value_gradient(x);
      EXPECT_LT(std::abs(g.value), 1e-12);
      const Vec3 gr = o.ribbons[side]->value_gradient(x).gradient;
      EXPECT_LT(g.gradient.normalized().cross(gr.normalized()).norm(), 1e-9);
      EXPECT_GT(g.gradient.dot(gr), 0.0);
    }
  }
}

TEST(IPatchSurface, RuleAWeightsPassThroughTheReferencePoint) {
  const Octant o;
  std::mt19937 rng(2);
  for (int i = 0; i < 50; ++i) {
    Vec3 c = random_in_octant(rng).normalized() * 0.9;  // inside every ribbon: R_i(c) < 0
    const IPatchSurface f = o.patch(c);
    EXPECT_LT(std::abs(f.value(c)), 1e-13);
    EXPECT_LT(std::abs(f.plain_value(c)), 1e-13);
  }
}

TEST(IPatchSurface, RuleAIsInvariantUnderScalingARibbon) {
  Octant o;
  const Vec3 c(0.5, 0.7, 0.45);
  const IPatchSurface f = o.patch(c);
  o.ribbons[1] = surface(ball_cylinder(Vec3::Zero(), Vec3::UnitX(), 1.0) * 7.5);
  const IPatchSurface g = o.patch(c);
  std::mt19937 rng(3);
  for (int i = 0; i < 500; ++i) {
    const Vec3 x = random_in_octant(rng);
    EXPECT_NEAR(f.plain_value(x) * g.plain_value(c + Vec3::Constant(0.1)),
                g.plain_value(x) * f.plain_value(c + Vec3::Constant(0.1)), 1e-12);
  }
}

TEST(IPatchSurface, NormalizedFormAgreesInSignWithThePlainOne) {
  const Octant o;
  const IPatchSurface f = o.patch(Vec3(0.6, 0.4, 0.5));
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 x(u(rng), u(rng), u(rng));
    const double plain = f.plain_value(x), normalized = f.value(x);
    if (std::abs(plain) < 1e-300) continue;
    EXPECT_EQ(plain > 0.0, normalized > 0.0) << x.transpose();
    ++checked;
  }
  EXPECT_GT(checked, 1900);
}

TEST(IPatchSurface, GradientAndHessianMatchCentralDifferences) {
  const Octant o;
  const IPatchSurface f = o.patch(Vec3(0.5, 0.7, 0.45));
  std::mt19937 rng(5);
  const double h = 1e-5;
  for (int i = 0; i < 200; ++i) {
    const Vec3 x = random_in_octant(rng);
    const SecondOrder s = f.second_order(x);
    EXPECT_DOUBLE_EQ(s.value, f.value(x));
    for (int k = 0; k < 3; ++k) {
      const Vec3 d = h * Vec3::Unit(k);
      const double fd = (f.value(x + d) - f.value(x - d)) / (2 * h);
      EXPECT_NEAR(s.gradient(k), fd, 1e-6 * (1.0 + std::abs(fd)));
      const Vec3 gd = (f.value_gradient(x + d).gradient - f.value_gradient(x - d).gradient) / (2 * h);
      for (int l = 0; l < 3; ++l) EXPECT_NEAR(s.hessian(l, k), gd(l), 1e-5 * (1.0 + std::abs(gd(l))));
    }
    EXPECT_LT((s.hessian - s.hessian.transpose()).norm(), 1e-9);
  }
}

TEST(IPatchSurface, NeverNaNWhereTwoBoundsVanish) {
  const Octant o;
  const IPatchSurface f = o.patch(Vec3(0.5, 0.7, 0.45));
  // On the x axis, B_0 = z and B_2 = y vanish: the mean of ribbons 0 and 2.
  for (double x : {0.0, 0.3, 1.0, 2.0}) {
    const Vec3 p(x, 0.0, 0.0);
    const SecondOrder s = f.second_order(p);
    EXPECT_TRUE(std::isfinite(s.value) && s.gradient.allFinite() && s.hessian.allFinite());
    EXPECT_NEAR(s.value, 0.5 * (o.ribbons[0]->value(p) + o.ribbons[2]->value(p)), 1e-15);
    EXPECT_EQ(f.plain_value(p), 0.0);  // the plain form vanishes on the whole curve: never mesh it
  }
  EXPECT_TRUE(std::isfinite(f.value(Vec3::Zero())));
}

TEST(IPatchSurface, RegionMarginIsTheSmallestBound) {
  const Octant o;
  const IPatchSurface f = o.patch(Vec3(0.5, 0.7, 0.45));
  EXPECT_DOUBLE_EQ(f.region_margin(Vec3(0.3, 0.2, 0.9)), 0.2);
  EXPECT_LT(f.region_margin(Vec3(0.3, -0.2, 0.9)), 0.0);
}

TEST(IPatchSurface, RuleARefusesABadReferencePoint) {
  const Octant o;
  EXPECT_THROW(o.patch(Vec3(-0.1, 0.5, 0.5)), InputError);  // outside the region
  EXPECT_THROW(o.patch(Vec3(0.3, 0.3, 1.2)), InputError);   // inside some ribbons, outside others
  EXPECT_THROW(rule_a_weights(o.ribbons, o.bounds, Vec3(0.5, 0.5, 0.5), {1.0, 2.0}, "octant"), InputError);
  EXPECT_THROW(rule_a_weights(o.ribbons, o.bounds, Vec3(0.5, 0.5, 0.5), {1.0, 0.0, 1.0}, "octant"),
               InputError);
}

TEST(QuadricSurface, IntervalBoundsHoldEverySample) {
  const Quadric pieces[] = {
      Quadric::from(plane_through(Vec3(0.1, 0.2, 0.3), Vec3(1.0, -2.0, 0.5))),
      liming_quadric(plane_through(Vec3(1, 0, 0), Vec3(1, 1, 0)), plane_through(Vec3(0, 1, 0), Vec3(0, 1, 1)),
                     plane_through(Vec3(1, 0, 0), Vec3(1, 1, 1)), 0.8, -1.0),
      ball_cylinder(Vec3(0.2, -0.3, 0.1), Vec3(1.0, 2.0, -1.0), 0.4)};
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-2.0, 2.0), w(0.01, 1.0), t(0.0, 1.0);
  for (const Quadric& q : pieces) {
    const QuadricSurface s("q", kBox, q);
    for (int i = 0; i < 100; ++i) {
      const Vec3 lo(u(rng), u(rng), u(rng));
      const Box box{lo, lo + Vec3(w(rng), w(rng), w(rng))};
      const auto bound = s.gradient_bound(box);
      ASSERT_TRUE(bound.has_value());
      for (int j = 0; j < 20; ++j) {
        const Vec3 x = box.lo + (box.hi - box.lo).cwiseProduct(Vec3(t(rng), t(rng), t(rng)));
        const ValueGradient vg = s.value_gradient(x);
        EXPECT_TRUE(bound->value.contains(vg.value));
        for (int k = 0; k < 3; ++k) EXPECT_TRUE(bound->gradient[k].contains(vg.gradient(k)));
      }
    }
  }
}

TEST(QuadricSurface, BallCylinderIsDistanceLikeOnItsSurface) {
  const Vec3 e = Vec3(1.0, 2.0, -1.0).normalized();
  const QuadricSurface s("cylinder", kBox, ball_cylinder(Vec3(0.2, -0.3, 0.1), e, 0.4));
  const Vec3 x = Vec3(0.2, -0.3, 0.1) + 0.7 * e + 0.4 * e.unitOrthogonal();
  EXPECT_NEAR(s.value(x), 0.0, 1e-15);
  EXPECT_NEAR(s.value_gradient(x).gradient.norm(), 1.0, 1e-14);
  EXPECT_THROW(ball_cylinder(Vec3::Zero(), e, 0.0), InputError);
}

}  // namespace
}  // namespace isopatch
