// Newton projection onto f = 0 along the gradient.
#include "surface/project_point.hpp"

#include <cmath>

namespace isopatch {

bool project_to_surface(const Sampler& f, Vec3& p, double tolerance, double max_step, Vec3* gradient) {
  for (int it = 0; it < 30; ++it) {
    const ValueGradient vg = f.value_gradient(p);
    const double g2 = vg.gradient.squaredNorm();
    if (!(g2 > 0.0)) return false;
    const double distance = std::abs(vg.value) / std::sqrt(g2);
    if (distance <= tolerance) {
      if (gradient) *gradient = vg.gradient;
      return true;
    }
    Vec3 step = vg.value / g2 * vg.gradient;
    const double length = step.norm();
    if (length > max_step) step *= max_step / length;
    p -= step;
  }
  return false;
}

}  // namespace isopatch
