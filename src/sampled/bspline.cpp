// Cubic B-spline prefilter and basis (bspline.hpp).
#include "sampled/bspline.hpp"

namespace isopatch::bspline {

namespace {

/// Solves, in place along one line of n values at stride `stride`, the system
///   4 c0 + 2 c1 = 6 v0,  c[i-1] + 4 c[i] + c[i+1] = 6 v[i],  2 c[n-2] + 4 c[n-1] = 6 v[n-1]
/// (the interpolation condition with c[-1] = c[1] and c[n] = c[n-2]) by the Thomas algorithm.
/// `scratch` holds n modified upper-diagonal entries.
void solve_line(double* v, std::size_t n, std::size_t stride, std::vector<double>& scratch) {
  scratch.resize(n);
  // Forward sweep: row i is  a_i c[i-1] + 4 c[i] + b_i c[i+1] = 6 v[i].
  double upper = 2.0;  // b_0
  double diag = 4.0;
  scratch[0] = upper / diag;
  v[0] = 6.0 * v[0] / diag;
  for (std::size_t i = 1; i < n; ++i) {
    const double lower = i == n - 1 ? 2.0 : 1.0;
    upper = 1.0;
    diag = 4.0 - lower * scratch[i - 1];
    scratch[i] = upper / diag;
    v[i * stride] = (6.0 * v[i * stride] - lower * v[(i - 1) * stride]) / diag;
  }
  // Back substitution.
  for (std::size_t i = n - 1; i-- > 0;) v[i * stride] -= scratch[i] * v[(i + 1) * stride];
}

}  // namespace

void interpolating_coefficients(std::vector<double>& values, const std::array<std::size_t, 3>& shape) {
  const std::size_t n0 = shape[0], n1 = shape[1], n2 = shape[2];
  std::vector<double> scratch;
  for (std::size_t i = 0; i < n0; ++i)
    for (std::size_t j = 0; j < n1; ++j) solve_line(&values[(i * n1 + j) * n2], n2, 1, scratch);
  for (std::size_t i = 0; i < n0; ++i)
    for (std::size_t k = 0; k < n2; ++k) solve_line(&values[i * n1 * n2 + k], n1, n2, scratch);
  for (std::size_t j = 0; j < n1; ++j)
    for (std::size_t k = 0; k < n2; ++k) solve_line(&values[j * n2 + k], n0, n1 * n2, scratch);
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
