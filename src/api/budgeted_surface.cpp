// Evaluation and time budgets around a Surface (see budgeted_surface.hpp).
#include "api/budgeted_surface.hpp"

namespace isopatch {

BudgetedSurface::BudgetedSurface(const Surface& inner, std::uint64_t max_evaluations, double seconds)
    : Surface(inner.name(), inner.box()), inner_(inner), budget_(max_evaluations, seconds) {}

double BudgetedSurface::value(const Vec3& p) const {
  charge(1);
  return inner_.value(p);
}

void BudgetedSurface::values(std::span<const Vec3> points, std::span<double> out) const {
  charge(points.size());
  inner_.values(points, out);
}

ValueGradient BudgetedSurface::value_gradient(const Vec3& p) const {
  charge(1);
  return inner_.value_gradient(p);
}

void BudgetedSurface::value_gradients(std::span<const Vec3> points, std::span<ValueGradient> out) const {
  charge(points.size());
  inner_.value_gradients(points, out);
}

SecondOrder BudgetedSurface::second_order(const Vec3& p) const {
  charge(1);
  return inner_.second_order(p);
}

std::optional<Interval> BudgetedSurface::bound(const Box& box) const {
  charge(1);
  return inner_.bound(box);
}

std::optional<IntervalGradient> BudgetedSurface::gradient_bound(const Box& box) const {
  charge(1);
  return inner_.gradient_bound(box);
}

}  // namespace isopatch
