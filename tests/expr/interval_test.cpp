// Interval bounds are sound: every value computed at a point of a box lies in the box's bound, for
// every function, for the catalogue, and on boxes straddling the edges of the domains.
#include "function_cases.hpp"

#include <isopatch/catalogue.hpp>
#include <isopatch/expression.hpp>
#include <isopatch/interval_math.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "random_box.hpp"

namespace isopatch {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Corners, face centres and random inner points of a box.
std::vector<Vec3> sample(const Box& b, std::mt19937_64& rng) {
  std::vector<Vec3> points;
  for (int corner = 0; corner < 8; ++corner)
    points.emplace_back(corner & 1 ? b.hi.x() : b.lo.x(), corner & 2 ? b.hi.y() : b.lo.y(),
                        corner & 4 ? b.hi.z() : b.lo.z());
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 12; ++i)
    points.push_back(b.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(b.hi - b.lo));
  return points;
}

struct Tally {
  int values = 0;
  int gradients = 0;
};

void check_containment(const std::string& formula, const Box& region, int boxes, Tally& tally,
                       unsigned seed) {
  SCOPED_TRACE(formula);
  const Expression f = parse_expression(formula);
  std::mt19937_64 rng(seed);
  for (int i = 0; i < boxes; ++i) {
    const Box box = test::random_box(region, rng, i);
    const Interval bound = f.bound(box);
    const IntervalGradient gb = f.gradient_bound(box);
    for (const Vec3& p : sample(box, rng)) {
      const double v = f.value(p);
      if (std::isnan(v)) continue;
      ASSERT_TRUE(bound.contains(v)) << v << " not in [" << bound.lo << ", " << bound.hi << "] at "
                                     << p.transpose() << " box " << box.lo.transpose() << " / "
                                     << box.hi.transpose();
      ASSERT_TRUE(gb.value.contains(v)) << v << " not in [" << gb.value.lo << ", " << gb.value.hi << "]";
      ++tally.values;
      const Vec3 g = f.value_gradient(p).gradient;
      for (int k = 0; k < 3; ++k) {
        if (std::isnan(g[k])) continue;
        const Interval& gk = gb.gradient[static_cast<std::size_t>(k)];
        ASSERT_TRUE(gk.contains(g[k]))
            << "d/d"
            << "xyz"[k] << " = " << g[k] << " not in [" << gk.lo << ", " << gk.hi << "] at " << p.transpose()
            << " box " << box.lo.transpose() << " / " << box.hi.transpose();
        ++tally.gradients;
      }
    }
  }
}

TEST(ExpressionIntervals, ContainEveryFunctionOnRandomBoxes) {
  Tally tally;
  unsigned seed = 1;
  for (const test::FunctionCase& c : test::function_cases())
    check_containment(c.formula, c.box, 150, tally, ++seed);
  EXPECT_GT(tally.values, 50000);
  EXPECT_GT(tally.gradients, 100000);
}

TEST(ExpressionIntervals, ContainTheCatalogue) {
  Tally tally;
  unsigned seed = 100;
  for (const CatalogueEntry& e : catalogue())
    check_containment(std::string(e.formula), e.box, 200, tally, ++seed);
  EXPECT_GT(tally.values, 40000);
}

TEST(ExpressionIntervals, ContainAtTheEdgesOfDomains) {
  // Boxes straddle 0 (a third of them) and the region covers both signs: division by intervals
  // containing 0, sqrt / log / fractional powers at and past the edge of their domain, poles of tan.
  const Box region{Vec3::Constant(-2.0), Vec3::Constant(2.0)};
  const char* formulas[] = {
      "1/x",
      "x/y",
      "(x + y)/(y*z)",
      "sqrt(x)",
      "log(x)",
      "x^0.5",
      "x^-1.5",
      "x^-2",
      "x^-3 + y^3",
      "pow(x, y)",
      "pow(x, 3)",
      "x^y^z",
      "tan(3*x)",
      "asin(2*x)",
      "acos(x*y)",
      "atan2(y, x)",
      "atan2(x*y, z)",
      "hypot(x, y)",
      "sin(5*x)*cos(4*y)",
      "sqrt(x*y) + log(z)",
      "abs(x) + min(y, z) - max(x, 0.1)",
      "exp(x*y*z)",
      "cosh(x) - sinh(y) * tanh(z)",
      "x^3e6",
      "1/(x^2 + y^2)",
  };
  Tally tally;
  unsigned seed = 200;
  for (const char* f : formulas) check_containment(f, region, 200, tally, ++seed);
  EXPECT_GT(tally.values, 40000);
}

TEST(IntervalMath, DomainEdgesAndDivisionByZero) {
  const Interval r1 = Interval{1.0, 2.0} / Interval{-1.0, 1.0};
  EXPECT_EQ(r1.lo, -kInf);
  EXPECT_EQ(r1.hi, kInf);
  const Interval r2 = Interval{1.0, 2.0} / Interval{0.0, 4.0};
  EXPECT_LE(r2.lo, 0.25);
  EXPECT_GT(r2.lo, 0.2499);
  EXPECT_EQ(r2.hi, kInf);
  const Interval s = sqrt(Interval{-1.0, 4.0});
  EXPECT_EQ(s.lo, 0.0);
  EXPECT_GE(s.hi, 2.0);
  EXPECT_LT(s.hi, 2.0 + 1e-12);
  EXPECT_TRUE(sqrt(Interval{-2.0, -1.0}).empty());
  const Interval l = log(Interval{0.0, 1.0});
  EXPECT_EQ(l.lo, -kInf);
  EXPECT_GE(l.hi, 0.0);
  EXPECT_TRUE(log(Interval{-2.0, -1.0}).empty());
  EXPECT_TRUE((sqrt(Interval{-2.0, -1.0}) + Interval{0.0, 1.0}).empty());
  const Interval p = pow(Interval{-2.0, 3.0}, 0.5);
  EXPECT_EQ(p.lo, 0.0);
  EXPECT_GE(p.hi, std::sqrt(3.0));
  const Interval q = pow(Interval{-2.0, 3.0}, 2.0);
  EXPECT_EQ(q.lo, 0.0);
  EXPECT_GE(q.hi, 9.0);
  // pow with a varying exponent reaches negative values only through negative bases at odd integers.
  const Interval n = pow(Interval{-2.0, -1.0}, Interval{2.5, 3.5});
  EXPECT_LE(n.lo, -8.0);
  // A base interval ending at 0 with negative exponents: |x|^-3 grows without bound near 0 on both
  // sides (fuzzing found the negated end -0, where pow(-0, -3) = -inf had hidden that).
  const Interval z = pow(Interval{-4.0, 3.0}, Interval{-3.0, 1e-9});
  EXPECT_EQ(z.lo, -kInf);
  EXPECT_EQ(z.hi, kInf);
  const Interval w = pow(Interval{-4.0, 0.0}, Interval{-3.0, -3.0});
  EXPECT_EQ(w.lo, -kInf);
  // atan2(0, -0) = pi in IEEE arithmetic: an x interval touching 0 with y containing 0 spans every
  // angle (fuzzing found atan2(y, -0) at y = 0 outside the bound).
  const Interval a = atan2(Interval{-1.0, 1.0}, Interval{0.0, 0.0});
  EXPECT_LE(a.lo, -std::numbers::pi);
  EXPECT_GE(a.hi, std::numbers::pi);
}

TEST(IntervalMath, TightWhereItShouldBe) {
  const Interval sq = sqr(Interval{-1.0, 2.0});
  EXPECT_EQ(sq.lo, 0.0);
  EXPECT_NEAR(sq.hi, 4.0, 1e-14);
  const Interval s = sin(Interval{0.1, 3.0});
  EXPECT_EQ(s.hi, 1.0);
  EXPECT_NEAR(s.lo, std::sin(0.1), 1e-14);  // sin(0.1) < sin(3.0)
  const Interval c = cos(Interval{-0.5, 4.0});
  EXPECT_EQ(c.hi, 1.0);
  EXPECT_EQ(c.lo, -1.0);
  const Interval t = tan(Interval{-1.0, 1.0});
  EXPECT_NEAR(t.hi, std::tan(1.0), 1e-14);
  EXPECT_EQ(tan(Interval{1.0, 2.0}).hi, kInf);  // contains the pole at pi/2
  // The bound of the compiled formula x^2 is that of sqr, not of x*x: [0, 4], not [-2, 4].
  const Interval b = parse_expression("x^2").bound(Box{Vec3(-1, -1, -1), Vec3(2, 1, 1)});
  EXPECT_EQ(b.lo, 0.0);
  EXPECT_NEAR(b.hi, 4.0, 1e-14);
  // The sphere's bound over a box far from the surface excludes 0.
  const Interval far = parse_expression("x^2 + y^2 + z^2 - 1").bound(Box{Vec3(2, 2, 2), Vec3(3, 3, 3)});
  EXPECT_FALSE(far.contains_zero());
}

}  // namespace
}  // namespace isopatch
