/// \file patch_region.cpp
/// A patch's region and the march inside it (patch_region.hpp).
#include "composite/patch_region.hpp"

#include <cmath>
#include <limits>

#include "surface/bracketed_root.hpp"

namespace isopatch {

PatchRegion::PatchRegion(const CompositePatch& patch, double tolerance)
    : bounds_(patch.bounds), tolerance_(tolerance) {}

double PatchRegion::depth(const Vec3& x) const {
  double depth = std::numeric_limits<double>::infinity();
  for (const SurfacePtr& b : bounds_) {
    const ValueGradient vg = b->value_gradient(x);
    if (!std::isfinite(vg.value)) throw_not_finite("a bounding function", vg.value, x);
    if (!vg.gradient.allFinite())
      throw_not_finite("the gradient of a bounding function", vg.gradient.norm(), x);
    const double g = vg.gradient.norm();
    const double d = g > 0.0 ? vg.value / g
                             : (vg.value >= 0.0 ? std::numeric_limits<double>::infinity()
                                                : -std::numeric_limits<double>::infinity());
    depth = std::min(depth, d);
  }
  return depth;
}

std::optional<RegionHit> march_in_region(const Sampler& f, const PatchRegion& region, const Vec3& start,
                                         double f_start, const Vec3& direction, double max_distance,
                                         int steps) {
  const Vec3 d = (f_start >= 0.0 ? -1.0 : 1.0) * direction.normalized();
  const double step = max_distance / steps;
  const bool start_negative = f_start < 0.0;
  bool was_inside = region.inside(start);
  double t_prev = 0.0;
  double f_prev = f_start;
  for (int i = 1; i <= steps; ++i) {
    const double t = step * i;
    const Vec3 q = start + t * d;
    const double fq = f.value(q);
    const bool in = region.inside(q);
    if ((fq < 0.0) != start_negative) {
      const auto phi = [&](double s) { return f.value(start + s * d); };
      const double s = bracketed_root(phi, t_prev, f_prev, t, fq, 1e-13 * max_distance);
      const Vec3 x = start + s * d;
      if (region.inside(x)) return RegionHit{x, f.value_gradient(x).gradient, d};
      return std::nullopt;  // the first crossing lies outside the region
    }
    if (was_inside && !in) return std::nullopt;
    was_inside = was_inside || in;
    t_prev = t;
    f_prev = fq;
  }
  return std::nullopt;
}

}  // namespace isopatch
