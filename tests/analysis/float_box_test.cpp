// FloatBox (src/analysis/triangle_tree.hpp): the self-intersection check's boxes in floats hold the
// doubles they are made of, and are the tightest floats that do.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "analysis/triangle_tree.hpp"

namespace isopatch {
namespace {

void expect_tight_around(double x) {
  analysis::FloatBox box;
  box.add(Vec3::Constant(x), Vec3::Constant(x));
  const float lo = box.lo.x(), hi = box.hi.x();
  EXPECT_LE(static_cast<double>(lo), x) << x;
  EXPECT_GE(static_cast<double>(hi), x) << x;
  // The next float inwards no longer holds x (or lo, hi are x itself).
  if (static_cast<double>(lo) != x) {
    EXPECT_GT(static_cast<double>(std::nextafter(lo, std::numeric_limits<float>::infinity())), x) << x;
  }
  if (static_cast<double>(hi) != x) {
    EXPECT_LT(static_cast<double>(std::nextafter(hi, -std::numeric_limits<float>::infinity())), x) << x;
  }
}

TEST(FloatBox, HoldsEveryDoubleTightly) {
  for (const double x : {0.0, -0.0, 1.0, -1.0, 0.1, -0.1, 1e-50, -1e-50, 1e-40, -1e-40, 3.4e38, -3.4e38, 1e39,
                         -1e39, std::numeric_limits<double>::denorm_min(), 16777217.0, -16777217.0})
    expect_tight_around(x);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-140, 130);
  for (int k = 0; k < 100000; ++k) expect_tight_around(std::ldexp(mantissa(rng), exponent(rng)));
}

}  // namespace
}  // namespace isopatch
