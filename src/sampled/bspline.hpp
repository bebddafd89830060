#pragma once
// Uniform cubic B-splines on a grid: the prefilter that turns samples into interpolating coefficients
// and the basis weights (with first and second derivatives) of one cell. Mirror-symmetric boundaries:
// the coefficient of index -i is that of i, and of n-1+i that of n-1-i.

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

}  // namespace isopatch::bspline
