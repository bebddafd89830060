// Single-sheet tests on general convex cells (convex_cell_tests.hpp).
#include "partition/convex_cell_tests.hpp"

#include <algorithm>
#include <cmath>

namespace isopatch {

bool in_plane_gradients_agree(std::span<const Vec3> gradients, const Vec3& normal) {
  for (const Vec3& g : gradients)
    if (!g.allFinite()) return false;
  auto in_plane = [&normal](const Vec3& g) { return Vec3(g - g.dot(normal) * normal); };
  for (std::size_t i = 0; i < gradients.size(); ++i) {
    const Vec3 a = in_plane(gradients[i]);
    if (!(a.squaredNorm() > 0.0)) return false;
    for (std::size_t j = i + 1; j < gradients.size(); ++j)
      if (!(a.dot(in_plane(gradients[j])) > 0.0)) return false;
  }
  return true;
}

bool segment_monotone_by_interval(const Surface& surface, const Vec3& a, const Vec3& b) {
  const Box bounds{a.cwiseMin(b), a.cwiseMax(b)};
  const auto bound = surface.gradient_bound(bounds);
  if (!bound) return false;
  const Vec3 d = b - a;
  double lo = 0.0, hi = 0.0;
  for (int k = 0; k < 3; ++k) {
    const Interval& g = bound->gradient[static_cast<std::size_t>(k)];
    if (g.empty()) return false;
    if (d[k] == 0.0) continue;
    const double x = d[k] * g.lo, y = d[k] * g.hi;
    lo += std::min(x, y);
    hi += std::max(x, y);
  }
  // A margin for the rounding of the sums above: the certificate must be sound.
  const double margin = 1e-12 * (std::abs(lo) + std::abs(hi));
  return std::isfinite(lo) && std::isfinite(hi) && (lo > margin || hi < -margin);
}

}  // namespace isopatch
