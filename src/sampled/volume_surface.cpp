// The tricubic B-spline interpolant of a sampled volume as a Surface (volume_surface.hpp).
#include <isopatch/error.hpp>
#include <isopatch/volume_surface.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include "sampled/bspline.hpp"

namespace isopatch {

namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

class VolumeSurface final : public Surface {
 public:
  VolumeSurface(Volume volume, double level, std::string name)
      : Surface(std::move(name), volume.extent()),
        shape_(volume.shape),
        spacing_(volume.spacing),
        origin_(volume.origin),
        level_(level),
        coefficients_(std::move(volume.samples)) {
    bspline::interpolating_coefficients(coefficients_, shape_);
    double largest = 0.0;
    for (const double c : coefficients_) largest = std::max(largest, std::abs(c));
    // Rounding in a sum of 64 products: a relative margin far above it keeps the bounds sound.
    slack_ = 1e-12 * (largest + std::abs(level_));
  }

  double value(const Vec3& p) const override { return evaluate<0>(p).value; }
  ValueGradient value_gradient(const Vec3& p) const override {
    const SecondOrder s = evaluate<1>(p);
    return {s.value, s.gradient};
  }
  SecondOrder second_order(const Vec3& p) const override { return evaluate<2>(p); }
  std::optional<Interval> bound(const Box& box) const override { return hull(box, false).value; }
  std::optional<IntervalGradient> gradient_bound(const Box& box) const override { return hull(box, true); }

 private:
  double coefficient(std::size_t i, std::size_t j, std::size_t k) const {
    return coefficients_[(i * shape_[1] + j) * shape_[2] + k];
  }

  /// Value (order 0), with gradient (1), with Hessian (2), of s - level at p.
  template <int Order>
  SecondOrder evaluate(const Vec3& p) const {
    std::array<std::array<std::size_t, 4>, 3> index;
    std::array<bspline::Weights, 3> w;
    for (int a = 0; a < 3; ++a) {
      const double u = (p[a] - origin_[a]) / spacing_[a];
      // Far outside, the mirror repeats the grid; a NaN or huge coordinate gives NaN, which callers check.
      if (!(std::abs(u) < 1e15)) {
        SecondOrder s;
        s.value = std::numeric_limits<double>::quiet_NaN();
        return s;
      }
      const double cell = std::floor(u);
      w[static_cast<std::size_t>(a)] = bspline::weights(u - cell);
      const auto base = static_cast<std::int64_t>(cell) - 1;
      for (int m = 0; m < 4; ++m)
        index[static_cast<std::size_t>(a)][static_cast<std::size_t>(m)] =
            bspline::mirror(base + m, shape_[static_cast<std::size_t>(a)]);
    }
    SecondOrder s;
    const auto& [wx, wy, wz] = w;
    for (std::size_t a = 0; a < 4; ++a)
      for (std::size_t b = 0; b < 4; ++b) {
        // The inner sums over z for this (x, y) pair: value, d/dz, d2/dz2.
        double c0 = 0.0, c1 = 0.0, c2 = 0.0;
        for (std::size_t c = 0; c < 4; ++c) {
          const double coef = coefficient(index[0][a], index[1][b], index[2][c]);
          c0 += wz.w[c] * coef;
          if constexpr (Order >= 1) c1 += wz.d1[c] * coef;
          if constexpr (Order >= 2) c2 += wz.d2[c] * coef;
        }
        s.value += wx.w[a] * wy.w[b] * c0;
        if constexpr (Order >= 1) {
          s.gradient[0] += wx.d1[a] * wy.w[b] * c0;
          s.gradient[1] += wx.w[a] * wy.d1[b] * c0;
          s.gradient[2] += wx.w[a] * wy.w[b] * c1;
        }
        if constexpr (Order >= 2) {
          s.hessian(0, 0) += wx.d2[a] * wy.w[b] * c0;
          s.hessian(1, 1) += wx.w[a] * wy.d2[b] * c0;
          s.hessian(2, 2) += wx.w[a] * wy.w[b] * c2;
          s.hessian(0, 1) += wx.d1[a] * wy.d1[b] * c0;
          s.hessian(0, 2) += wx.d1[a] * wy.w[b] * c1;
          s.hessian(1, 2) += wx.w[a] * wy.d1[b] * c1;
        }
      }
    s.value -= level_;
    for (int a = 0; a < 3; ++a) s.gradient[a] /= spacing_[a];
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b) {
        s.hessian(a, b) /= spacing_[a] * spacing_[b];
        s.hessian(b, a) = s.hessian(a, b);
      }
    return s;
  }

  /// Convex-hull bounds over `box`: the coefficients whose basis functions reach it (cells
  /// floor(u_lo) .. floor(u_hi), coefficients one before to two after), and with `gradient` the
  /// differences of neighbours among them along each axis.
  IntervalGradient hull(const Box& box, bool gradient) const {
    IntervalGradient r;
    std::array<std::vector<std::size_t>, 3> index;
    for (int a = 0; a < 3; ++a) {
      const std::size_t n = shape_[static_cast<std::size_t>(a)];
      const double lo = (box.lo[a] - origin_[a]) / spacing_[a], hi = (box.hi[a] - origin_[a]) / spacing_[a];
      if (!(std::abs(lo) < 1e12 && std::abs(hi) < 1e12 && lo <= hi)) return r;  // unbounded
      const auto first = static_cast<std::int64_t>(std::floor(lo)) - 1;
      const auto last = static_cast<std::int64_t>(std::floor(hi)) + 2;
      auto& axis = index[static_cast<std::size_t>(a)];
      // Beyond a whole period of the mirror (2 (n - 1) indices) nothing new is reached.
      const std::int64_t end = std::min(last, first + 2 * static_cast<std::int64_t>(n) + 1);
      for (std::int64_t i = first; i <= end; ++i) axis.push_back(bspline::mirror(i, n));
    }
    const double inf = std::numeric_limits<double>::infinity();
    double vlo = inf, vhi = -inf;
    std::array<double, 3> glo{inf, inf, inf}, ghi{-inf, -inf, -inf};
    for (std::size_t a = 0; a < index[0].size(); ++a)
      for (std::size_t b = 0; b < index[1].size(); ++b)
        for (std::size_t c = 0; c < index[2].size(); ++c) {
          const double v = coefficient(index[0][a], index[1][b], index[2][c]);
          vlo = std::min(vlo, v);
          vhi = std::max(vhi, v);
          if (!gradient) continue;
          const double d[3] = {
              a + 1 < index[0].size() ? coefficient(index[0][a + 1], index[1][b], index[2][c]) - v : 0.0,
              b + 1 < index[1].size() ? coefficient(index[0][a], index[1][b + 1], index[2][c]) - v : 0.0,
              c + 1 < index[2].size() ? coefficient(index[0][a], index[1][b], index[2][c + 1]) - v : 0.0};
          const bool has[3] = {a + 1 < index[0].size(), b + 1 < index[1].size(), c + 1 < index[2].size()};
          for (int g = 0; g < 3; ++g)
            if (has[g]) {
              glo[static_cast<std::size_t>(g)] = std::min(glo[static_cast<std::size_t>(g)], d[g]);
              ghi[static_cast<std::size_t>(g)] = std::max(ghi[static_cast<std::size_t>(g)], d[g]);
            }
        }
    r.value = {vlo - level_ - slack_, vhi - level_ + slack_};
    if (gradient)
      for (int g = 0; g < 3; ++g) {
        const auto gi = static_cast<std::size_t>(g);
        r.gradient[gi] = {(glo[gi] - slack_) / spacing_[g], (ghi[gi] + slack_) / spacing_[g]};
      }
    return r;
  }

  std::array<std::size_t, 3> shape_;
  Vec3 spacing_;
  Vec3 origin_;
  double level_;
  std::vector<double> coefficients_;
  double slack_ = 0.0;
};

}  // namespace

SurfacePtr volume_surface(Volume volume, double level, std::string name) {
  volume.validate();
  if (!std::isfinite(level)) throw InputError("the level must be finite", "level");
  const auto [lo, hi] = std::minmax_element(volume.samples.begin(), volume.samples.end());
  if (!(*lo < level) || !(*hi >= level))
    throw NoSurfaceError("no sample of the volume crosses level " + number(level) +
                         " (the samples range over [" + number(*lo) + ", " + number(*hi) + "])");
  return std::make_shared<VolumeSurface>(std::move(volume), level, std::move(name));
}

}  // namespace isopatch
