// Cubic B-spline prefilter and basis (bspline.hpp).
#include "sampled/bspline.hpp"

namespace isopatch::bspline {

namespace {

/// The Thomas algorithm's factors for the system of one grid line of n values
///   4 c0 + 2 c1 = 6 v0,  c[i-1] + 4 c[i] + c[i+1] = 6 v[i],  2 c[n-2] + 4 c[n-1] = 6 v[n-1]
/// (the interpolation condition with c[-1] = c[1] and c[n] = c[n-2]): per row its lower entry, its
/// diagonal after elimination and its upper entry divided by that diagonal. They depend on n alone, so
/// every line of an axis shares them.
struct LineFactors {
  std::vector<double> lower, diag, upper;

  /// \pre n >= 2.
  explicit LineFactors(std::size_t n) : lower(n), diag(n), upper(n) {
    for (std::size_t i = 0; i < n; ++i) {
      lower[i] = i + 1 == n ? 2.0 : 1.0;  // row 0 has none
      diag[i] = i == 0 ? 4.0 : 4.0 - lower[i] * upper[i - 1];
      upper[i] = (i == 0 ? 2.0 : 1.0) / diag[i];
    }
  }
};

/// Solves the system in place for `count` lines at once whose values i lie at v[i * stride + l],
/// l < count (lines side by side in memory, so the sweeps run along cache lines). Every line sees the
/// same operations in the same order as it would alone.
void solve_lines(double* v, std::size_t n, std::size_t stride, std::size_t count, const LineFactors& f) {
  for (std::size_t l = 0; l < count; ++l) v[l] = 6.0 * v[l] / f.diag[0];
  for (std::size_t i = 1; i < n; ++i) {
    double* row = v + i * stride;
    const double* before = row - stride;
    for (std::size_t l = 0; l < count; ++l) row[l] = (6.0 * row[l] - f.lower[i] * before[l]) / f.diag[i];
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    double* row = v + i * stride;
    const double* after = row + stride;
    for (std::size_t l = 0; l < count; ++l) row[l] -= f.upper[i] * after[l];
  }
}

/// The same for one line of contiguous values (the last axis).
void solve_line(double* v, std::size_t n, const LineFactors& f) {
  v[0] = 6.0 * v[0] / f.diag[0];
  for (std::size_t i = 1; i < n; ++i) v[i] = (6.0 * v[i] - f.lower[i] * v[i - 1]) / f.diag[i];
  for (std::size_t i = n - 1; i-- > 0;) v[i] -= f.upper[i] * v[i + 1];
}

}  // namespace

void interpolating_coefficients(std::span<double> values, const std::array<std::size_t, 3>& shape) {
  const std::size_t n0 = shape[0], n1 = shape[1], n2 = shape[2];
  const LineFactors along0(n0), along1(n1), along2(n2);
  for (std::size_t line = 0; line < n0 * n1; ++line) solve_line(&values[line * n2], n2, along2);
  for (std::size_t i = 0; i < n0; ++i) solve_lines(&values[i * n1 * n2], n1, n2, n2, along1);
  solve_lines(values.data(), n0, n1 * n2, n1 * n2, along0);
}

Weights weights(double t) {
  const double s = 1.0 - t, t2 = t * t, t3 = t2 * t;
  Weights w;
  w.w = {s * s * s / 6.0, (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0, (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0,
         t3 / 6.0};
  w.d1 = {-0.5 * s * s, 1.5 * t2 - 2.0 * t, -1.5 * t2 + t + 0.5, 0.5 * t2};
  w.d2 = {s, 3.0 * t - 2.0, 1.0 - 3.0 * t, t};
  return w;
}

}  // namespace isopatch::bspline
