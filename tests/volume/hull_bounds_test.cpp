// The convex-hull bounds of a sampled volume over large boxes come from brick summaries; they must be
// exactly the bounds a scan of every coefficient the box reaches gives, mirror included.
#include <gtest/gtest.h>
#include <isopatch/volume_surface.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace isopatch {
namespace {

/// Index i reflected into [0, n - 1] about the first and last samples.
std::size_t reflect(std::int64_t i, std::size_t n) {
  const std::int64_t period = 2 * (static_cast<std::int64_t>(n) - 1);
  std::int64_t m = ((i % period) + period) % period;
  if (m >= static_cast<std::int64_t>(n)) m = period - m;
  return static_cast<std::size_t>(m);
}

/// The bounds by visiting every coefficient (and every pair of neighbours) the box reaches: the
/// coefficients of cells floor(u_lo) - 1 .. floor(u_hi) + 2 along each axis, mirrored.
IntervalGradient scanned(const std::vector<double>& c, const Volume& v, double level, const Box& box) {
  std::array<std::vector<std::size_t>, 3> index;
  for (std::size_t a = 0; a < 3; ++a) {
    const int ai = static_cast<int>(a);
    const double lo = (box.lo[ai] - v.origin[ai]) / v.spacing[ai],
                 hi = (box.hi[ai] - v.origin[ai]) / v.spacing[ai];
    const auto first = static_cast<std::int64_t>(std::floor(lo)) - 1;
    const auto last = std::min(static_cast<std::int64_t>(std::floor(hi)) + 2,
                               first + 2 * static_cast<std::int64_t>(v.shape[a]) + 1);
    for (std::int64_t i = first; i <= last; ++i) index[a].push_back(reflect(i, v.shape[a]));
  }
  const auto at = [&](std::size_t i, std::size_t j, std::size_t k) {
    return c[(i * v.shape[1] + j) * v.shape[2] + k];
  };
  const double inf = std::numeric_limits<double>::infinity();
  double vlo = inf, vhi = -inf;
  std::array<double, 3> glo{inf, inf, inf}, ghi{-inf, -inf, -inf};
  for (std::size_t a = 0; a < index[0].size(); ++a)
    for (std::size_t b = 0; b < index[1].size(); ++b)
      for (std::size_t k = 0; k < index[2].size(); ++k) {
        const double x = at(index[0][a], index[1][b], index[2][k]);
        vlo = std::min(vlo, x);
        vhi = std::max(vhi, x);
        const std::array<bool, 3> next{a + 1 < index[0].size(), b + 1 < index[1].size(),
                                       k + 1 < index[2].size()};
        for (std::size_t g = 0; g < 3; ++g) {
          if (!next[g]) continue;
          const double d = (g == 0   ? at(index[0][a + 1], index[1][b], index[2][k])
                            : g == 1 ? at(index[0][a], index[1][b + 1], index[2][k])
                                     : at(index[0][a], index[1][b], index[2][k + 1])) -
                           x;
          glo[g] = std::min(glo[g], d);
          ghi[g] = std::max(ghi[g], d);
        }
      }
  IntervalGradient r;
  const double slack = 1e-12 * (std::max(std::abs(vlo), std::abs(vhi)) + std::abs(level));
  r.value = {vlo - level - slack, vhi - level + slack};
  for (std::size_t g = 0; g < 3; ++g)
    r.gradient[g] = {(glo[g] - slack) / v.spacing[static_cast<int>(g)],
                     (ghi[g] + slack) / v.spacing[static_cast<int>(g)]};
  return r;
}

TEST(VolumeHullBounds, LargeBoxesGiveExactlyTheScannedBounds) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Volume v;
  v.shape = {37, 21, 45};  // no side a multiple of the brick
  v.spacing = Vec3(0.5, 0.25, 1.0);
  v.origin = Vec3(-3, 1, 0);
  for (std::size_t n = 0; n < 37 * 21 * 45; ++n) v.samples.push_back(u(rng));
  std::vector<double> c = v.samples;
  interpolating_coefficients(c, v.shape);
  const double level = 0.1;
  const SurfacePtr s = volume_surface(v, level);
  const Box extent = v.extent();
  std::uniform_real_distribution<double> t(-0.7, 1.7);  // reaches past both ends of the grid
  int large = 0;
  for (int n = 0; n < 400; ++n) {
    Box box;
    for (int a = 0; a < 3; ++a) {
      const double x = extent.lo[a] + t(rng) * (extent.hi[a] - extent.lo[a]);
      const double y = extent.lo[a] + t(rng) * (extent.hi[a] - extent.lo[a]);
      box.lo[a] = std::min(x, y);
      box.hi[a] = std::max(x, y);
    }
    const IntervalGradient want = scanned(c, v, level, box);
    const auto got = s->gradient_bound(box);
    const auto value = s->bound(box);
    ASSERT_TRUE(got && value);
    EXPECT_EQ(got->value.lo, want.value.lo) << n;
    EXPECT_EQ(got->value.hi, want.value.hi) << n;
    EXPECT_EQ(value->lo, want.value.lo) << n;
    EXPECT_EQ(value->hi, want.value.hi) << n;
    for (std::size_t g = 0; g < 3; ++g) {
      EXPECT_EQ(got->gradient[g].lo, want.gradient[g].lo) << n << " axis " << g;
      EXPECT_EQ(got->gradient[g].hi, want.gradient[g].hi) << n << " axis " << g;
    }
    const double cells = (box.hi - box.lo).cwiseQuotient(v.spacing).prod();
    large += cells > 8000.0 ? 1 : 0;
  }
  EXPECT_GT(large, 100);  // most boxes are far beyond the scanned size: the summaries answer them
}

}  // namespace
}  // namespace isopatch
