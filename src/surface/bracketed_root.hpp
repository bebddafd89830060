#pragma once
// A bracketed scalar root finder shared by every mesher: the Illinois variant of regula falsi
// (Dowell & Jarratt 1971) with a bisection safeguard. Illinois halves the value kept at a stagnant end,
// which restores superlinear convergence where plain regula falsi crawls; bisection whenever two steps
// did not halve the bracket bounds the worst case to plain bisection.

#include <algorithm>
#include <cmath>
#include <limits>

namespace isopatch {

/// Finds t between a and b with phi(t) = 0, given fa = phi(a) and fb = phi(b) of opposite signs under
/// the sign rule (v >= 0 positive). Stops when the bracket is at most `tolerance` wide, phi is exactly 0,
/// the bracket is down to adjacent doubles, or after `max_iterations` evaluations. Returns the end of
/// the final bracket with the smaller |phi| (an end whose value is exactly 0 is returned as is).
template <class Phi>
double bracketed_root(Phi&& phi, double a, double fa, double b, double fb, double tolerance,
                      int max_iterations = 100) {
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  double t_neg = fa < 0.0 ? a : b, g_neg = fa < 0.0 ? fa : fb;
  double t_pos = fa < 0.0 ? b : a, g_pos = fa < 0.0 ? fb : fa;
  double true_neg = g_neg, true_pos = g_pos;  // unhalved values, to pick the better end
  int last_moved = 0;                         // -1: the negative end moved last, +1: the positive end
  double width_last = std::numeric_limits<double>::infinity();
  double width_before_last = width_last;
  for (int step = 0; step < max_iterations; ++step) {
    const double width = std::abs(t_pos - t_neg);
    if (width <= tolerance) break;
    const double lo = std::min(t_neg, t_pos), hi = std::max(t_neg, t_pos);
    double t = t_neg - g_neg * (t_pos - t_neg) / (g_pos - g_neg);
    if (!(t > lo && t < hi) || width > 0.5 * width_before_last) t = 0.5 * (lo + hi);
    if (!(t > lo && t < hi)) break;  // adjacent doubles
    width_before_last = width_last;
    width_last = width;
    const double g = phi(t);
    if (g == 0.0) return t;
    if (g < 0.0) {
      t_neg = t;
      g_neg = true_neg = g;
      if (last_moved == -1) g_pos *= 0.5;
      last_moved = -1;
    } else {
      t_pos = t;
      g_pos = true_pos = g;
      if (last_moved == +1) g_neg *= 0.5;
      last_moved = +1;
    }
  }
  return std::abs(true_neg) < std::abs(true_pos) ? t_neg : t_pos;
}

}  // namespace isopatch
