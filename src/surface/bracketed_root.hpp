#pragma once
// A bracketed scalar root finder: the Illinois variant of regula falsi with a bisection safeguard
// (Dowell & Jarratt 1971). Used for edge crossings and for the end of every ray march.

#include <cmath>
#include <utility>

namespace isopatch {

/// Finds t in [a, b] with phi(t) = 0, given phi(a) = fa and phi(b) = fb of opposite signs under the
/// sign rule (v >= 0 positive). Stops when the bracket is narrower than `tolerance` or after
/// `max_iterations`. Returns the end of the final bracket with the smaller |phi| (the exact root when
/// hit). Never leaves [a, b].
template <class Phi>
double bracketed_root(Phi&& phi, double a, double fa, double b, double fb, double tolerance,
                      int max_iterations = 100) {
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  int side = 0;  // which end was kept last time (Illinois halving)
  for (int it = 0; it < max_iterations && std::abs(b - a) > tolerance; ++it) {
    double t = (a * fb - b * fa) / (fb - fa);
    // Safeguard: fall back to bisection when the secant point is not strictly inside.
    if (!(t > std::min(a, b) && t < std::max(a, b))) t = 0.5 * (a + b);
    if (it % 4 == 3) t = 0.5 * (a + b);  // guarantees at least geometric shrinking of the bracket
    const double ft = phi(t);
    if (ft == 0.0) return t;
    if ((ft >= 0.0) == (fb >= 0.0)) {
      b = t;
      fb = ft;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = t;
      fa = ft;
      if (side == +1) fb *= 0.5;
      side = +1;
    }
  }
  return std::abs(fa) <= std::abs(fb) ? a : b;
}

}  // namespace isopatch
