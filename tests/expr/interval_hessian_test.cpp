// Interval Hessians (Expression::hessian_bound) are sound: the value, gradient and Hessian computed at
// any point of a box lie in the box's enclosures, for every function of the language, the catalogue and
// the singular-point test surfaces; and they are exact where they should be.
#include "function_cases.hpp"

#include <isopatch/catalogue.hpp>
#include <isopatch/expression.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "random_box.hpp"

namespace isopatch {
namespace {

constexpr int kHessianRow[6] = {0, 0, 0, 1, 1, 2};
constexpr int kHessianColumn[6] = {0, 1, 2, 1, 2, 2};

/// Checks every computed value, gradient and Hessian entry at corners and random points of random boxes;
/// adds the number of Hessian entries checked to `checked`.
void check(const std::string& formula, const Box& region, int boxes, unsigned seed, long& checked) {
  SCOPED_TRACE(formula);
  const Expression f = parse_expression(formula);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < boxes; ++i) {
    const Box box = test::random_box(region, rng, i);
    const IntervalHessian h = f.hessian_bound(box);
    const IntervalGradient g = f.gradient_bound(box);
    for (int s = 0; s < 16; ++s) {
      const Vec3 p = s < 8 ? Vec3(s & 1 ? box.hi.x() : box.lo.x(), s & 2 ? box.hi.y() : box.lo.y(),
                                  s & 4 ? box.hi.z() : box.lo.z())
                           : Vec3(box.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(box.hi - box.lo));
      const SecondOrder so = f.second_order(p);
      if (std::isnan(so.value)) continue;
      ASSERT_TRUE(h.value.contains(so.value)) << so.value << " at " << p.transpose();
      // The same value and gradient enclosures as the first-order evaluator's, operation for operation.
      ASSERT_EQ(h.value.lo, g.value.lo);
      ASSERT_EQ(h.value.hi, g.value.hi);
      for (int k = 0; k < 3; ++k) {
        if (std::isnan(so.gradient[k])) continue;
        ASSERT_TRUE(h.gradient[static_cast<std::size_t>(k)].contains(so.gradient[k])) << p.transpose();
      }
      for (int k = 0; k < 6; ++k) {
        const double v = so.hessian(kHessianRow[k], kHessianColumn[k]);
        if (std::isnan(v)) continue;
        const Interval& e = h.hessian[static_cast<std::size_t>(k)];
        ASSERT_TRUE(e.contains(v)) << "H"
                                   << "xyz"[kHessianRow[k]] << "xyz"[kHessianColumn[k]] << " = " << v
                                   << " not in [" << e.lo << ", " << e.hi << "] at " << p.transpose()
                                   << " box " << box.lo.transpose() << " / " << box.hi.transpose();
        ++checked;
      }
    }
  }
}

TEST(IntervalHessian, ContainsEveryFunctionOnRandomBoxes) {
  long checked = 0;
  unsigned seed = 7;
  for (const test::FunctionCase& c : test::function_cases()) check(c.formula, c.box, 120, ++seed, checked);
  EXPECT_GT(checked, 200000);
}

TEST(IntervalHessian, ContainsTheCatalogueAndTheSingularSurfaces) {
  long checked = 0;
  unsigned seed = 300;
  for (const CatalogueEntry& e : catalogue()) check(std::string(e.formula), e.box, 150, ++seed, checked);
  const Box cube{Vec3::Constant(-1.9), Vec3::Constant(1.9)};
  check("(x^2+y^2+z^2+2*y-1)*((x^2+y^2+z^2-2*y-1)^2-8*z^2)+16*x*z*(x^2+y^2+z^2-2*y-1)", cube, 150, 400,
        checked);
  check(
      "p=(1+sqrt(5))/2; (x^2-p^4*y^2)*(y^2-p^4*z^2)*(z^2-p^4*x^2)*(x^4+y^4+z^4-2*x^2*y^2-2*x^2*z^2-2*y^2*z^2)"
      "-(1+2*p)/4*(x^2+y^2+z^2-1)^2",
      cube, 150, 401, checked);
  EXPECT_GT(checked, 100000);
}

TEST(IntervalHessian, TightForAQuadraticAndWholeLineAtAKink) {
  const Box box{Vec3(-0.3, 0.2, -1.0), Vec3(0.4, 0.9, -0.5)};
  // x^2 + 2 y^2 - 3 x z + y: the Hessian is constant, the enclosure a point (up to the outward rounding
  // of a few ulps).
  const IntervalHessian q = parse_expression("x^2 + 2*y^2 - 3*x*z + y").hessian_bound(box);
  const double expected[6] = {2.0, 0.0, -3.0, 4.0, 0.0, 0.0};
  for (int k = 0; k < 6; ++k) {
    const Interval& e = q.hessian[static_cast<std::size_t>(k)];
    EXPECT_TRUE(e.contains(expected[k])) << k;
    EXPECT_LT(e.width(), 1e-14) << k;
  }
  // abs across 0 has no Hessian to bound: its entries are the whole line (the gradient jumps).
  const IntervalHessian a =
      parse_expression("abs(x + y)").hessian_bound(Box{Vec3(-1, -1, -1), Vec3(1, 1, 1)});
  EXPECT_TRUE(std::isinf(a.hessian[0].lo) && std::isinf(a.hessian[0].hi));
  // Away from the kink it is exact again (0).
  const IntervalHessian b = parse_expression("abs(x + y)").hessian_bound(Box{Vec3(1, 1, -1), Vec3(2, 2, 1)});
  EXPECT_TRUE(b.hessian[0].contains(0.0));
  EXPECT_LT(b.hessian[0].width(), 1e-14);
}

}  // namespace
}  // namespace isopatch
