// Forward-mode derivatives against central differences, and the catalogue formulas against the same
// surfaces written as C++ callables (tests/support/test_surfaces.hpp).
#include "function_cases.hpp"
#include "test_surfaces.hpp"

#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace isopatch {
namespace {

Vec3 random_point(const Box& box, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.05, 0.95);  // keep the difference stencil inside
  Vec3 p;
  for (int k = 0; k < 3; ++k) p[k] = box.lo[k] + u(rng) * (box.hi[k] - box.lo[k]);
  return p;
}

TEST(ExpressionDerivatives, MatchCentralDifferencesForEveryFunction) {
  std::mt19937_64 rng(42);
  const double h = 1e-5;
  for (const test::FunctionCase& c : test::function_cases()) {
    SCOPED_TRACE(c.formula);
    const Expression f = parse_expression(c.formula);
    int checked = 0;
    for (int trial = 0; trial < 200; ++trial) {
      const Vec3 p = random_point(c.box, rng);
      if (c.kink && c.kink(p) < 1e-3) continue;
      const SecondOrder s = f.second_order(p);
      const ValueGradient vg = f.value_gradient(p);
      ASSERT_TRUE(std::isfinite(s.value));
      EXPECT_EQ(vg.value, s.value);
      Mat3 hessian_fd;
      for (int k = 0; k < 3; ++k) {
        const Vec3 e = h * Vec3::Unit(k);
        const double g_fd = (f.value(p + e) - f.value(p - e)) / (2.0 * h);
        EXPECT_NEAR(s.gradient[k], g_fd, 1e-6 * (1.0 + std::fabs(g_fd)))
            << "d/d"
            << "xyz"[k] << " at " << p.transpose();
        EXPECT_NEAR(vg.gradient[k], s.gradient[k], 1e-13 * (1.0 + std::fabs(g_fd)));
        hessian_fd.col(k) = (f.value_gradient(p + e).gradient - f.value_gradient(p - e).gradient) / (2.0 * h);
      }
      // The differenced matrix is not symmetric by construction: agreeing with it entry by entry
      // checks the symmetric Hessian and its symmetry.
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          EXPECT_NEAR(s.hessian(i, j), hessian_fd(i, j), 1e-5 * (1.0 + std::fabs(hessian_fd(i, j))))
              << "(" << i << "," << j << ") at " << p.transpose();
          EXPECT_EQ(s.hessian(i, j), s.hessian(j, i));
        }
      ++checked;
    }
    EXPECT_GT(checked, 150);
  }
}

TEST(ExpressionDerivatives, CatalogueFormulasAgreeWithCallables) {
  const std::pair<const char*, SurfacePtr> pairs[] = {{"sphere", test::sphere()},
                                                      {"torus", test::torus()},
                                                      {"tanglecube", test::tanglecube()},
                                                      {"genus2", test::genus2()}};
  std::mt19937_64 rng(5);
  for (const auto& [name, callable] : pairs) {
    SCOPED_TRACE(name);
    const SurfacePtr formula = catalogue_surface(name);
    EXPECT_TRUE(formula->box().lo.isApprox(callable->box().lo));
    EXPECT_TRUE(formula->box().hi.isApprox(callable->box().hi));
    for (int trial = 0; trial < 500; ++trial) {
      const Vec3 p = random_point(callable->box(), rng);
      const SecondOrder a = formula->second_order(p);
      const SecondOrder b = callable->second_order(p);
      const double scale = 1.0 + std::fabs(b.value) + b.gradient.norm() + b.hessian.norm();
      EXPECT_NEAR(formula->value(p), callable->value(p), 1e-13 * scale);
      EXPECT_NEAR(a.value, b.value, 1e-13 * scale);
      EXPECT_LT((a.gradient - b.gradient).norm(), 1e-13 * scale);
      EXPECT_LT((a.hessian - b.hessian).norm(), 1e-13 * scale);
      EXPECT_LT((formula->value_gradient(p).gradient - b.gradient).norm(), 1e-13 * scale);
    }
  }
}

TEST(ExpressionDerivatives, KnownValues) {
  // f = x^2 y + sin(z): gradient (2xy, x^2, cos z), Hessian [[2y, 2x, 0], [2x, 0, 0], [0, 0, -sin z]].
  const Expression f = parse_expression("x^2*y + sin(z)");
  const Vec3 p(1.5, -2.0, 0.25);
  const SecondOrder s = f.second_order(p);
  EXPECT_DOUBLE_EQ(s.value, 1.5 * 1.5 * -2.0 + std::sin(0.25));
  EXPECT_DOUBLE_EQ(s.gradient.x(), 2 * 1.5 * -2.0);
  EXPECT_DOUBLE_EQ(s.gradient.y(), 1.5 * 1.5);
  EXPECT_DOUBLE_EQ(s.gradient.z(), std::cos(0.25));
  Mat3 expected;
  expected << -4.0, 3.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, -std::sin(0.25);
  EXPECT_LT((s.hessian - expected).norm(), 1e-14);
}

}  // namespace
}  // namespace isopatch
