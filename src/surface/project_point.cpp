// Newton projection onto f = 0 along the gradient.
#include "surface/project_point.hpp"

#include <cmath>

namespace isopatch {

namespace {

/// Newton steps along grad f with the components of `frozen` (1 = frozen) removed.
bool newton(const Sampler& f, Vec3& p, const Vec3& frozen, double tolerance, double max_step,
            Vec3* gradient) {
  for (int it = 0; it < 30; ++it) {
    const ValueGradient vg = f.value_gradient(p);
    const Vec3 direction = vg.gradient.cwiseProduct(Vec3::Ones() - frozen);
    const double g2 = direction.squaredNorm();
    if (!(g2 > 0.0)) return false;
    const double distance = std::abs(vg.value) / std::sqrt(g2);
    if (distance <= tolerance) {
      if (gradient) *gradient = vg.gradient;
      return true;
    }
    Vec3 step = vg.value / g2 * direction;
    const double length = step.norm();
    if (length > max_step) step *= max_step / length;
    p -= step;
  }
  return false;
}

}  // namespace

bool project_to_surface(const Sampler& f, Vec3& p, double tolerance, double max_step, Vec3* gradient) {
  return newton(f, p, Vec3::Zero(), tolerance, max_step, gradient);
}

bool project_to_surface_in_plane(const Sampler& f, Vec3& p, int axis, double tolerance, double max_step,
                                 Vec3* gradient) {
  return newton(f, p, Vec3::Unit(axis), tolerance, max_step, gradient);
}

}  // namespace isopatch
