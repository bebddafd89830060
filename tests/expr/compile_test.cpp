// Compilation: shared subexpressions, folded constants, printing and re-parsing, batch evaluation.
#include "function_cases.hpp"

#include <isopatch/catalogue.hpp>
#include <isopatch/expression.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>
#include <vector>

namespace isopatch {
namespace {

std::size_t tape_size(const std::string& formula) {
  return parse_expression(formula).tape_size();
}

std::vector<Vec3> random_points(const Box& box, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> points(n);
  for (Vec3& p : points)
    for (int k = 0; k < 3; ++k) p[k] = box.lo[k] + u(rng) * (box.hi[k] - box.lo[k]);
  return points;
}

TEST(ExpressionCompile, CommonSubexpressionsAreShared) {
  EXPECT_EQ(tape_size("sin(x) + sin(x)"), tape_size("2*sin(x)"));
  EXPECT_LT(tape_size("sin(x) + sin(x)"), tape_size("sin(x) + sin(y)"));
  EXPECT_EQ(tape_size("(x^2 + y^2)^2 + (x^2 + y^2)"), 5u);  // x^2, y^2, +, ^2, +
  EXPECT_EQ(tape_size("x^4 + x^2"), 3u);                    // x^4 is (x^2)^2
  EXPECT_EQ(tape_size("x*x + x^2"), 2u);                    // x*x is x^2; a + a is 2*a
  EXPECT_EQ(tape_size("x*y + y*x"), 2u);                    // commutative operands are ordered
  EXPECT_EQ(tape_size("a = exp(z); b = a + 1; a*b + b"), 4u);
}

TEST(ExpressionCompile, ConstantsAreFolded) {
  EXPECT_EQ(tape_size("2*3 + x"), 1u);
  EXPECT_EQ(tape_size("2*3 + x"), tape_size("x + 6"));
  EXPECT_EQ(tape_size("R = 2; r = 0.5; x*(R^2 - r^2)"), 1u);
  EXPECT_EQ(tape_size("sin(pi/2) * cos(0) * x"), 0u);  // folds to x itself
  EXPECT_EQ(tape_size("2*pi"), 1u);
  EXPECT_DOUBLE_EQ(parse_expression("2*pi").value(Vec3::Zero()), 2.0 * std::numbers::pi);
  EXPECT_EQ(tape_size("unused = sin(y)*exp(z); x"), 0u);  // dead definitions are dropped
}

TEST(ExpressionCompile, PrintingAndParsingAgainGivesTheSameValues) {
  std::vector<std::string> formulas;
  for (const test::FunctionCase& c : test::function_cases()) formulas.push_back(c.formula);
  for (const CatalogueEntry& e : catalogue()) formulas.emplace_back(e.formula);
  formulas.emplace_back("x - 0.4 + 1e-300*y - 1e300*z + (-0.0)*x + 1/(x - x)");
  formulas.emplace_back("min(x, 0) + 2^x + atan2(1, y) + x^0.5 + x^7 + x^-3 + x^3e6");
  for (const std::string& f : formulas) {
    const Expression original = parse_expression(f);
    const std::string printed = to_string(original);
    SCOPED_TRACE(f + "  ->  " + printed);
    const Expression again = parse_expression(printed);
    EXPECT_EQ(again.tape_size(), original.tape_size());
    for (const Vec3& p : random_points(Box{Vec3::Constant(-2.0), Vec3::Constant(2.0)}, 50, 7)) {
      const double a = original.value(p), b = again.value(p);
      if (std::isnan(a)) {
        EXPECT_TRUE(std::isnan(b));
      } else {
        EXPECT_EQ(a, b);
      }
    }
  }
}

TEST(ExpressionCompile, BatchAgreesWithSinglePoints) {
  for (const test::FunctionCase& c : test::function_cases()) {
    SCOPED_TRACE(c.formula);
    const Expression f = parse_expression(c.formula);
    const std::vector<Vec3> points = random_points(c.box, 1000, 11);  // not a multiple of the block
    std::vector<double> batch(points.size()), soa(points.size());
    f.values(points, batch);
    std::vector<double> xs, ys, zs;
    for (const Vec3& p : points) {
      xs.push_back(p.x());
      ys.push_back(p.y());
      zs.push_back(p.z());
    }
    f.values(xs.data(), ys.data(), zs.data(), soa.data(), points.size());
    for (const std::size_t small : {1u, 7u, 9u, 300u}) {  // partial blocks on their own
      std::vector<double> part(small);
      f.values(std::span(points).first(small), part);
      for (std::size_t i = 0; i < small; ++i) ASSERT_EQ(part[i], batch[i]) << small << " " << i;
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double v = f.value(points[i]);
      ASSERT_EQ(batch[i], v) << i;
      ASSERT_EQ(soa[i], v) << i;
      ASSERT_EQ(f.value_gradient(points[i]).value, v) << i;
      ASSERT_EQ(f.second_order(points[i]).value, v) << i;
    }
  }
}

TEST(ExpressionCompile, EvaluatesConcurrently) {
  const Expression f = parse_expression(std::string(find_in_catalogue("tanglecube")->formula));
  const std::vector<Vec3> points = random_points(Box{Vec3::Constant(-2.0), Vec3::Constant(2.0)}, 4000, 3);
  std::vector<double> expected(points.size());
  f.values(points, expected);
  std::vector<int> mismatches(2, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t)
    threads.emplace_back([&, t] {
      std::vector<double> out(points.size());
      for (int round = 0; round < 20; ++round) {
        f.values(points, out);
        for (std::size_t i = 0; i < points.size(); ++i) {
          mismatches[t] += out[i] != expected[i];
          mismatches[t] += f.value_gradient(points[i]).value != expected[i];
        }
      }
    });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(mismatches[0] + mismatches[1], 0);
}

TEST(ExpressionCompile, MinAndMaxPropagateNaNAlike) {
  // Found by fuzz_expression: min(a, NaN) used to return a, so a point could take a finite value where
  // part of f is undefined and fall outside the (sound) interval bound of the defined points.
  const Expression f = parse_expression("min(z^2.5, x) + max(x, sqrt(z))");
  const Vec3 p(0.5, 0.0, -1.0);  // z^2.5 and sqrt(z) are NaN there
  EXPECT_TRUE(std::isnan(f.value(p)));
  std::vector<Vec3> batch{p, Vec3(0.5, 0.0, 1.0)};
  std::vector<double> out(2);
  f.values(batch, out);
  EXPECT_TRUE(std::isnan(out[0]));
  EXPECT_DOUBLE_EQ(out[1], f.value(batch[1]));
  EXPECT_TRUE(std::isnan(f.value_gradient(p).value));
  EXPECT_TRUE(std::isnan(f.second_order(p).value));
  const Expression g = parse_expression(
      "min(x^2+y^2+z^2.5, abs(- x^2*y)^2+z^2-9-9, max(abs(x)-1.5, abs(- x^2*y)^2+z^2-9, -2))");
  const Interval bound = g.bound(Box{Vec3::Constant(-1), Vec3::Constant(1)});
  const double v = g.value(Vec3(-1, 1, -1));
  EXPECT_TRUE(std::isnan(v) || bound.contains(v));
}

TEST(ExpressionCompile, PowAndHypotAreUndefinedWhereAnyPartIs) {
  // Found by fuzz_expression: IEEE's pow(1, NaN) = 1, pow(-inf, -5.5) = 0, pow(-0.5, inf) = 0 and
  // hypot(inf, NaN) = inf made f finite where the interval extension (rightly) calls it undefined.
  const Vec3 p(0.5, -0.5, -1.0);
  for (const char* formula : {"1^sqrt(z)", "(0.9 - x^-68719476736)^(x - 6)", "(y)^(1/0 + x)",
                              "hypot(1/0 + x, sqrt(z))", "x^(0/0)"}) {
    const Expression f = parse_expression(formula);
    EXPECT_TRUE(std::isnan(f.value(p))) << formula;
    std::vector<Vec3> batch{p};
    std::vector<double> out(1);
    f.values(batch, out);
    EXPECT_TRUE(std::isnan(out[0])) << formula;
    EXPECT_TRUE(std::isnan(f.second_order(p).value)) << formula;
  }
  EXPECT_DOUBLE_EQ(parse_expression("(-2)^3 + x^2").value(Vec3(3, 0, 0)), 1.0);  // integer powers stay
}

}  // namespace
}  // namespace isopatch
