// The exact orientation signs (analysis/exact_predicates.hpp) against integer arithmetic: points with
// small integer coordinates scaled by a power of two are exact doubles, and their determinant is exact
// in 128-bit integers. Random points (the double filter decides), coplanar and collinear ones (the
// exact expansions), shared points and points on one axis-aligned plane (every product of the
// permanent zero) all get the integers' sign.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "analysis/exact_predicates.hpp"

namespace isopatch::exact {
namespace {

using Point = std::array<std::int64_t, 3>;
__extension__ using Wide = __int128;  // exact for the determinants of coordinates under 2^21

int integer_orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
  Wide u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) u[i] = b[i] - a[i], v[i] = c[i] - a[i], w[i] = d[i] - a[i];
  const Wide det = u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
                   u[2] * (v[0] * w[1] - v[1] * w[0]);
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

Vec3 scaled(const Point& p, double scale) {
  return Vec3(static_cast<double>(p[0]) * scale, static_cast<double>(p[1]) * scale,
              static_cast<double>(p[2]) * scale);
}

TEST(ExactPredicates, Orient3dHasTheIntegersSignOnRandomDegenerateAndSharedPoints) {
  std::mt19937_64 random(7);
  std::uniform_int_distribution<std::int64_t> coordinate(-(1 << 20), 1 << 20);
  std::uniform_int_distribution<std::int64_t> small(-3, 3);
  const auto point = [&] { return Point{coordinate(random), coordinate(random), coordinate(random)}; };
  int zeros = 0, nonzeros = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Point a = point(), b = point(), c = point(), d = point();
    switch (trial % 5) {
      case 1:  // d in the plane of a, b, c: an integer combination
        for (int i = 0; i < 3; ++i)
          d[i] = a[i] + small(random) * (b[i] - a[i]) + small(random) * (c[i] - a[i]);
        break;
      case 2:  // a shared point
        d = trial % 2 ? a : c;
        break;
      case 3:  // all four on one axis-aligned plane (a cap)
        b[trial % 3] = c[trial % 3] = d[trial % 3] = a[trial % 3];
        break;
      case 4:  // nearly coplanar: one unit off the plane of an integer combination
        for (int i = 0; i < 3; ++i)
          d[i] = a[i] + small(random) * (b[i] - a[i]) + small(random) * (c[i] - a[i]);
        d[trial % 3] += 1;
        break;
      default:
        break;
    }
    const double scale = std::ldexp(1.0, static_cast<int>(trial % 41) - 20);
    const int expected = integer_orient3d(a, b, c, d);
    ASSERT_EQ(orient3d(scaled(a, scale), scaled(b, scale), scaled(c, scale), scaled(d, scale)), expected)
        << "trial " << trial;
    (expected == 0 ? zeros : nonzeros)++;
  }
  EXPECT_GT(zeros, 8000);
  EXPECT_GT(nonzeros, 8000);
}

TEST(ExactPredicates, Orient2dHasTheIntegersSign) {
  std::mt19937_64 random(11);
  std::uniform_int_distribution<std::int64_t> coordinate(-(1 << 24), 1 << 24);
  for (int trial = 0; trial < 20000; ++trial) {
    std::int64_t ax = coordinate(random), ay = coordinate(random), bx = coordinate(random),
                 by = coordinate(random), cx = coordinate(random), cy = coordinate(random);
    if (trial % 3 == 1) cx = ax + 2 * (bx - ax), cy = ay + 2 * (by - ay);  // collinear
    if (trial % 3 == 2) cx = bx, cy = by;                                  // a shared point
    const Wide det = static_cast<Wide>(bx - ax) * (cy - ay) - static_cast<Wide>(by - ay) * (cx - ax);
    const int expected = det > 0 ? 1 : (det < 0 ? -1 : 0);
    const auto d = [](std::int64_t x) { return static_cast<double>(x) * 0.125; };
    ASSERT_EQ(orient2d(d(ax), d(ay), d(bx), d(by), d(cx), d(cy)), expected) << "trial " << trial;
  }
}

}  // namespace
}  // namespace isopatch::exact
