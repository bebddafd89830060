#pragma once
// Uniform cubic B-splines on a grid: the prefilter that turns samples into interpolating coefficients
// and the basis weights (with first and second derivatives) of one cell. Mirror-symmetric boundaries:
// the coefficient of index -i is that of i, and of n-1+i that of n-1-i.

#include <isopatch/derivatives.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace isopatch::bspline {

/// Replaces `values` (C order, `shape`) by the coefficients c of the tricubic B-spline that
/// interpolates them: (c[i-1] + 4 c[i] + c[i+1]) / 6 = value[i] along every axis, with the mirror
/// boundary. One tridiagonal (Thomas) solve per grid line and axis. \pre every side >= 2.
void interpolating_coefficients(std::span<double> values, const std::array<std::size_t, 3>& shape);

/// Index i of a grid of n >= 2 samples, reflected into [0, n-1] (period 2 (n - 1)).
inline std::size_t mirror(std::int64_t i, std::size_t n) {
  const std::int64_t period = 2 * (static_cast<std::int64_t>(n) - 1);
  std::int64_t m = i % period;
  if (m < 0) m += period;
  if (m >= static_cast<std::int64_t>(n)) m = period - m;
  return static_cast<std::size_t>(m);
}

/// The four basis weights of coefficients i-1 .. i+2 at t in [0, 1] inside cell [i, i+1], and their
/// first and second derivatives with respect to t.
struct Weights {
  std::array<double, 4> w, d1, d2;
};
Weights weights(double t);

/// The tricubic B-spline at a point of one cell, in the grid's index coordinates: the value (Order 0),
/// with the gradient (1), with the Hessian (2), from the cell's weights along x, y, z and
/// `coefficient(a, b, c)`, the coefficient of offsets a, b, c in 0..3 (indices i-1 .. i+2). Scale by
/// the spacing with to_world(). Every grid (dense, sparse) sums in this one order, so equal
/// coefficients give equal bits.
template <int Order, class Coefficient>
SecondOrder tricubic(const std::array<Weights, 3>& w, Coefficient&& coefficient) {
  SecondOrder s;
  const auto& [wx, wy, wz] = w;
  for (std::size_t a = 0; a < 4; ++a)
    for (std::size_t b = 0; b < 4; ++b) {
      // The inner sums over z for this (x, y) pair: value, d/dz, d2/dz2.
      double c0 = 0.0, c1 = 0.0, c2 = 0.0;
      for (std::size_t c = 0; c < 4; ++c) {
        const double coef = coefficient(a, b, c);
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
  return s;
}

/// Index-space derivatives of tricubic() turned into derivatives in space: divided by the spacing along
/// each axis (once for the gradient, twice for the Hessian, which is made symmetric).
inline void to_world(SecondOrder& s, const Vec3& spacing) {
  for (int a = 0; a < 3; ++a) s.gradient[a] /= spacing[a];
  for (int a = 0; a < 3; ++a)
    for (int b = a; b < 3; ++b) {
      s.hessian(a, b) /= spacing[a] * spacing[b];
      s.hessian(b, a) = s.hessian(a, b);
    }
}

}  // namespace isopatch::bspline
