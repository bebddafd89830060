// Root finding on a grid edge. The bracket is kept in the edge parameter t in [0, 1], so the stopping
// rule (1e-13) is relative to the cell size and independent of the scale of f.
#include "mc/edge_root.hpp"

#include <isopatch/error.hpp>

#include "surface/bracketed_root.hpp"
#include "surface/sampler.hpp"

#include <cmath>

namespace isopatch::mc {

void check_value(double value, const Vec3& p) {
  if (!std::isfinite(value)) throw_not_finite("f", value, p);
}

double checked_value(const Surface& surface, const Vec3& p, std::uint64_t& evaluations) {
  const double value = surface.value(p);
  ++evaluations;
  check_value(value, p);
  return value;
}

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
      t = bracketed_root([&](double u) { return checked_value(surface, a + u * (b - a), evaluations); },
                         t_neg, g_neg, t_pos, g_pos, 1e-13);
  }
  if (t == 0.0) return a;
  if (t == 1.0) return b;
  // Clamped to the segment's bounding box: rounding must not push the point past b (a box face).
  return (a + t * (b - a)).cwiseMax(a.cwiseMin(b)).cwiseMin(a.cwiseMax(b));
}

}  // namespace isopatch::mc
