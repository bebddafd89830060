// Root finding on one grid edge.
#include "mc/edge_root.hpp"

#include <isopatch/callable_surface.hpp>
#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace isopatch {
namespace {

const Box kBox{Vec3::Constant(-2), Vec3::Constant(2)};

TEST(EdgeRoot, BracketedFindsTheRootOfACubic) {
  // Root of x^3 + x - 0.5 near 0.4239; the edge runs along x from 0 to 1 at y = z = 0.7.
  const SurfacePtr s = make_surface([](auto x, auto, auto) { return x * x * x + x - 0.5; }, kBox);
  std::uint64_t evaluations = 0;
  const Vec3 a(0, 0.7, 0.7), b(1, 0.7, 0.7);
  const Vec3 p = mc::edge_root(*s, a, b, s->value(a), s->value(b), EdgeRoot::Bracketed, evaluations);
  EXPECT_LE(std::abs(s->value(p)), 1e-13);
  EXPECT_EQ(p.y(), 0.7);  // stays exactly on the edge's line
  EXPECT_EQ(p.z(), 0.7);
  EXPECT_GT(evaluations, 0u);
  EXPECT_LE(evaluations, 20u);
}

TEST(EdgeRoot, BracketedIsSymmetricInTheEndpoints) {
  const SurfacePtr s = make_surface([](auto x, auto y, auto z) { return x * x + y * y + z * z - 1.0; }, kBox);
  std::uint64_t evaluations = 0;
  const Vec3 a(0.1, 0.2, 0.3), b(1.5, 0.2, 0.3);
  const Vec3 p = mc::edge_root(*s, a, b, s->value(a), s->value(b), EdgeRoot::Bracketed, evaluations);
  const Vec3 q = mc::edge_root(*s, b, a, s->value(b), s->value(a), EdgeRoot::Bracketed, evaluations);
  EXPECT_NEAR((p - q).norm(), 0.0, 1.5e-13);
  EXPECT_NEAR(p.norm(), 1.0, 1e-13);
}

TEST(EdgeRoot, FlatFunctionsStillConvergeWithinTheStepLimit) {
  // Regula falsi alone crawls on x^9: Illinois plus the bisection safeguard must not.
  const SurfacePtr s = make_surface(
      [](auto x, auto, auto) {
        using std::pow;
        return pow(x, 9) - 1e-6;
      },
      kBox);
  const double root = std::pow(1e-6, 1.0 / 9.0);
  std::uint64_t evaluations = 0;
  const Vec3 a(-0.3, 0, 0), b(1.7, 0, 0);
  const Vec3 p = mc::edge_root(*s, a, b, s->value(a), s->value(b), EdgeRoot::Bracketed, evaluations);
  EXPECT_NEAR(p.x(), root, 2 * 2e-13);
  EXPECT_LE(evaluations, 100u);
}

TEST(EdgeRoot, LinearInterpolatesTheEndValues) {
  const SurfacePtr s = make_surface([](auto x, auto, auto) { return x * x - 0.25; }, kBox);
  std::uint64_t evaluations = 0;
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  const Vec3 p = mc::edge_root(*s, a, b, -0.25, 0.75, EdgeRoot::Linear, evaluations);
  EXPECT_DOUBLE_EQ(p.x(), 0.25);
  EXPECT_EQ(evaluations, 0u);
}

TEST(EdgeRoot, ZeroEndIsTheRootExactly) {
  // f >= 0 counts as positive: a zero end is the positive end and is returned as is.
  const SurfacePtr s = make_surface([](auto x, auto, auto) { return x - 1.0; }, kBox);
  for (EdgeRoot mode : {EdgeRoot::Bracketed, EdgeRoot::Linear}) {
    std::uint64_t evaluations = 0;
    const Vec3 a(0.5, 0, 0), b(1, 0, 0);
    EXPECT_EQ(mc::edge_root(*s, a, b, -0.5, 0.0, mode, evaluations), b);
    EXPECT_EQ(mc::edge_root(*s, b, a, 0.0, -0.5, mode, evaluations), b);
    EXPECT_EQ(evaluations, 0u);
  }
}

TEST(EdgeRoot, NaNInsideTheEdgeIsAnEvaluationError) {
  // Finite at both ends, NaN in between.
  const SurfacePtr s = make_surface(
      [](auto x, auto, auto) {
        using std::sqrt;
        return (x - 0.5) * (x - 0.5) > 0.01 ? x - 0.45 : sqrt(x - 10.0);
      },
      kBox);
  std::uint64_t evaluations = 0;
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  try {
    mc::edge_root(*s, a, b, s->value(a), s->value(b), EdgeRoot::Bracketed, evaluations);
    FAIL() << "no error";
  } catch (const EvaluationError& e) {
    EXPECT_NE(std::string(e.what()).find("f is NaN at ("), std::string::npos) << e.what();
  }
}

TEST(EdgeRoot, CheckValueNamesInfinity) {
  try {
    mc::check_value(std::numeric_limits<double>::infinity(), Vec3(1, 2, 3));
    FAIL() << "no error";
  } catch (const EvaluationError& e) {
    EXPECT_EQ(std::string(e.what()), "f is infinite at (1, 2, 3)");
  }
  EXPECT_NO_THROW(mc::check_value(-1e300, Vec3::Zero()));
}

}  // namespace
}  // namespace isopatch
