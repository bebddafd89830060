// Root finding on a grid edge. The bracket is kept in the edge parameter t in [0, 1], so the stopping
// rule (1e-13) is relative to the cell size and independent of the scale of f. Illinois halves the
// value kept at a stagnant end, which restores superlinear convergence where plain regula falsi
// crawls; the bisection fallback bounds the worst case to the 43 halvings that 1e-13 needs.
#include "mc/edge_root.hpp"

#include <isopatch/error.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace isopatch::mc {

void check_value(double value, const Vec3& p) {
  if (std::isfinite(value)) return;
  char text[160];
  std::snprintf(text, sizeof text, "f is %s at (%.9g, %.9g, %.9g)", std::isnan(value) ? "NaN" : "inf", p.x(),
                p.y(), p.z());
  throw EvaluationError(text);
}

double checked_value(const Surface& surface, const Vec3& p, std::uint64_t& evaluations) {
  const double value = surface.value(p);
  ++evaluations;
  check_value(value, p);
  return value;
}

namespace {

constexpr double kTolerance = 1e-13;
constexpr int kMaxSteps = 100;

// Illinois iteration on g(t) = f(a + t (b - a)) with g(t_neg) < 0 <= g(t_pos); returns t.
double illinois(const Surface& surface, const Vec3& a, const Vec3& b, double t_neg, double g_neg,
                double t_pos, double g_pos, std::uint64_t& evaluations) {
  double true_neg = g_neg;  // unhalved values, to pick the better end at the end
  double true_pos = g_pos;
  int last_kept = 0;  // -1: the negative end moved last, +1: the positive end moved last
  // Bracket widths one and two steps ago (none yet).
  double width_before_last = std::numeric_limits<double>::infinity();
  double width_last = std::numeric_limits<double>::infinity();
  for (int step = 0; step < kMaxSteps; ++step) {
    const double width = std::abs(t_pos - t_neg);
    if (width <= kTolerance) break;
    double t = t_neg - g_neg * (t_pos - t_neg) / (g_pos - g_neg);
    const double lo = std::min(t_neg, t_pos);
    const double hi = std::max(t_neg, t_pos);
    // Bisect when the secant leaves the open bracket or two steps did not halve it.
    if (!(t > lo && t < hi) || width > 0.5 * width_before_last) t = 0.5 * (lo + hi);
    if (!(t > lo && t < hi)) break;  // the bracket is down to adjacent doubles
    width_before_last = width_last;
    width_last = width;
    const double g = checked_value(surface, a + t * (b - a), evaluations);
    if (g == 0.0) return t;
    if (g < 0.0) {
      t_neg = t;
      g_neg = true_neg = g;
      if (last_kept == -1) g_pos *= 0.5;
      last_kept = -1;
    } else {
      t_pos = t;
      g_pos = true_pos = g;
      if (last_kept == +1) g_neg *= 0.5;
      last_kept = +1;
    }
  }
  return std::abs(true_neg) < std::abs(true_pos) ? t_neg : t_pos;
}

}  // namespace

Vec3 edge_root(const Surface& surface, const Vec3& a, const Vec3& b, double fa, double fb, EdgeRoot mode,
               std::uint64_t& evaluations) {
  const bool a_negative = fa < 0.0;
  const double t_neg = a_negative ? 0.0 : 1.0;
  const double t_pos = 1.0 - t_neg;
  const double g_neg = a_negative ? fa : fb;
  const double g_pos = a_negative ? fb : fa;
  double t = t_pos;
  if (g_pos > 0.0) {
    if (mode == EdgeRoot::Linear)
      t = t_neg + (t_pos - t_neg) * (-g_neg / (g_pos - g_neg));
    else
      t = illinois(surface, a, b, t_neg, g_neg, t_pos, g_pos, evaluations);
  }
  if (t == 0.0) return a;
  if (t == 1.0) return b;
  return a + t * (b - a);
}

}  // namespace isopatch::mc
