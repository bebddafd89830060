#include "interior_seed.hpp"

#include <cmath>
#include <limits>

namespace isopatch::bench {

std::optional<Vec3> deepest_interior_sample(const Surface& surface, const Box& box, int n) {
  std::optional<Vec3> best;
  double best_depth = std::numeric_limits<double>::infinity();
  const Vec3 step = box.size() / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Vec3 p = box.lo + step.cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5));
        const ValueGradient vg = surface.value_gradient(p);
        if (!std::isfinite(vg.value) || !(vg.value < 0.0)) continue;
        const double g = vg.gradient.norm();
        // Where grad f vanishes inside, the point is as deep as it gets for this estimate.
        const double depth =
            (std::isfinite(g) && g > 0.0) ? vg.value / g : -std::numeric_limits<double>::max();
        if (depth < best_depth) {
          best_depth = depth;
          best = p;
        }
      }
  return best;
}

}  // namespace isopatch::bench
