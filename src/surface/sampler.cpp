#include "surface/sampler.hpp"

#include <isopatch/error.hpp>

#include <cmath>
#include <cstdio>

#include <tbb/task_arena.h>

namespace isopatch {

void throw_not_finite(const char* what, double value, const Vec3& p) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, "%s is %s at (%.9g, %.9g, %.9g)", what,
                std::isnan(value) ? "NaN" : "infinite", p.x(), p.y(), p.z());
  throw EvaluationError(buffer);
}

void SpreadCounter::add(std::uint64_t count) const {
  // -1 outside every arena (tbb::task_arena::not_initialized): slot 0.
  const int worker = tbb::this_task_arena::current_thread_index();
  const std::size_t slot = worker > 0 ? static_cast<std::size_t>(worker) % kSlots : 0;
  slots_[slot].count.fetch_add(count, std::memory_order_relaxed);
}

std::uint64_t SpreadCounter::total() const {
  std::uint64_t sum = 0;
  for (const Slot& s : slots_) sum += s.count.load(std::memory_order_relaxed);
  return sum;
}

double Sampler::value(const Vec3& p) const {
  values_.add();
  const double v = surface_.value(p);
  if (!std::isfinite(v)) throw_not_finite("f", v, p);
  return v;
}

void Sampler::values(std::span<const Vec3> points, std::span<double> out) const {
  values_.add(points.size());
  surface_.values(points, out);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(out[i])) throw_not_finite("f", out[i], points[i]);
}

ValueGradient Sampler::value_gradient(const Vec3& p) const {
  gradients_.add();
  const ValueGradient vg = surface_.value_gradient(p);
  if (!std::isfinite(vg.value)) throw_not_finite("f", vg.value, p);
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(vg.gradient[i])) throw_not_finite("grad f", vg.gradient[i], p);
  return vg;
}

void Sampler::value_gradients(std::span<const Vec3> points, std::span<ValueGradient> out) const {
  gradients_.add(points.size());
  surface_.value_gradients(points, out);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(out[i].value)) throw_not_finite("f", out[i].value, points[i]);
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(out[i].gradient[a])) throw_not_finite("grad f", out[i].gradient[a], points[i]);
  }
}

ValueGradient Sampler::value_gradient_unchecked(const Vec3& p) const {
  gradients_.add();
  return surface_.value_gradient(p);
}

}  // namespace isopatch
