#include "surface/sampler.hpp"

#include <isopatch/error.hpp>

#include <cmath>
#include <cstdio>

namespace isopatch {

void throw_not_finite(const char* what, double value, const Vec3& p) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, "%s is %s at (%.9g, %.9g, %.9g)", what,
                std::isnan(value) ? "NaN" : "infinite", p.x(), p.y(), p.z());
  throw EvaluationError(buffer);
}

double Sampler::value(const Vec3& p) const {
  values_.fetch_add(1, std::memory_order_relaxed);
  const double v = surface_.value(p);
  if (!std::isfinite(v)) throw_not_finite("f", v, p);
  return v;
}

ValueGradient Sampler::value_gradient(const Vec3& p) const {
  gradients_.fetch_add(1, std::memory_order_relaxed);
  const ValueGradient vg = surface_.value_gradient(p);
  if (!std::isfinite(vg.value)) throw_not_finite("f", vg.value, p);
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(vg.gradient[i])) throw_not_finite("grad f", vg.gradient[i], p);
  return vg;
}

ValueGradient Sampler::value_gradient_unchecked(const Vec3& p) const {
  gradients_.fetch_add(1, std::memory_order_relaxed);
  return surface_.value_gradient(p);
}

}  // namespace isopatch
