// Default implementations of the optional Surface services.
#include <isopatch/surface.hpp>

#include <cassert>

namespace isopatch {

void Surface::values(std::span<const Vec3> points, std::span<double> out) const {
  assert(out.size() == points.size());
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = value(points[i]);
}

void Surface::value_gradients(std::span<const Vec3> points, std::span<ValueGradient> out) const {
  assert(out.size() == points.size());
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = value_gradient(points[i]);
}

std::optional<Interval> Surface::bound(const Box&) const {
  return std::nullopt;
}

std::optional<IntervalGradient> Surface::gradient_bound(const Box&) const {
  return std::nullopt;
}

std::optional<IntervalHessian> Surface::hessian_bound(const Box&) const {
  return std::nullopt;
}

}  // namespace isopatch
