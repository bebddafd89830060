// Forward-mode derivatives of callable surfaces against central differences.
#include <isopatch/callable_surface.hpp>

#include <gtest/gtest.h>

#include <random>

#include "test_surfaces.hpp"

namespace isopatch {
namespace {

// Central-difference gradient and Hessian of s at p with step h.
void central_differences(const Surface& s, const Vec3& p, double h, Vec3& g, Mat3& H) {
  for (int i = 0; i < 3; ++i) {
    Vec3 e = Vec3::Zero();
    e[i] = h;
    g[i] = (s.value(p + e) - s.value(p - e)) / (2 * h);
    const Vec3 gp = s.value_gradient(p + e).gradient;
    const Vec3 gm = s.value_gradient(p - e).gradient;
    H.col(i) = (gp - gm) / (2 * h);
  }
}

void expect_derivatives_match(const SurfacePtr& s, std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const SecondOrder so = s->second_order(p);
    EXPECT_DOUBLE_EQ(so.value, s->value(p));
    Vec3 g;
    Mat3 H;
    central_differences(*s, p, 1e-5, g, H);
    const double scale = 1.0 + so.gradient.norm() + so.hessian.norm();
    EXPECT_LT((so.gradient - g).norm(), 1e-6 * scale) << s->name() << " at " << p.transpose();
    EXPECT_LT((so.hessian - H).norm(), 1e-5 * scale) << s->name() << " at " << p.transpose();
    EXPECT_LT((so.hessian - so.hessian.transpose()).norm(), 1e-12 * scale);
  }
}

TEST(Autodiff, PolynomialSurfacesMatchCentralDifferences) {
  std::mt19937 rng(7);
  expect_derivatives_match(test::sphere(), rng, -1.5, 1.5);
  expect_derivatives_match(test::torus(), rng, -1.5, 1.5);
  expect_derivatives_match(test::tanglecube(), rng, -2.0, 2.0);
  expect_derivatives_match(test::genus2(), rng, -1.0, 1.0);
}

TEST(Autodiff, ElementaryFunctionsMatchCentralDifferences) {
  const Box box{Vec3::Constant(-1), Vec3::Constant(1)};
  std::mt19937 rng(11);
  // Arguments kept inside each function's domain for the sampled range [0.1, 0.6].
  expect_derivatives_match(
      make_surface([](auto x, auto y, auto z) { return sin(x) * cos(y) + tan(z); }, box, "trig"), rng, 0.1,
      0.6);
  expect_derivatives_match(
      make_surface([](auto x, auto y, auto z) { return exp(x * y) + log(1.0 + z) + sqrt(x + 1.0); }, box,
                   "explog"),
      rng, 0.1, 0.6);
  expect_derivatives_match(
      make_surface([](auto x, auto y, auto z) { return asin(x) + acos(y) + atan(z) + atan2(y, x); }, box,
                   "inverse"),
      rng, 0.1, 0.6);
  expect_derivatives_match(
      make_surface([](auto x, auto y, auto z) { return sinh(x) + cosh(y) * tanh(z) + hypot(x, z); }, box,
                   "hyper"),
      rng, 0.1, 0.6);
  expect_derivatives_match(
      make_surface([](auto x, auto y, auto z) { return pow(x, 2.5) + pow(y, z) + abs(x - 0.7) / (1.0 + z); },
                   box, "pow"),
      rng, 0.1, 0.6);
}

TEST(Autodiff, MakeSurfaceRejectsEmptyBox) {
  EXPECT_THROW(make_surface([](auto x, auto, auto) { return x; }, Box{}, "empty"), InputError);
}

}  // namespace
}  // namespace isopatch
