// Evaluation and time budgets around a Surface (see budgeted_surface.hpp).
#include "surface/budgeted_surface.hpp"

#include <utility>

namespace isopatch {

BudgetedSurface::BudgetedSurface(const Surface& inner, std::uint64_t max_evaluations, double seconds)
    : BudgetedSurface(inner, std::make_shared<EvaluationBudget>(max_evaluations, seconds)) {}

BudgetedSurface::BudgetedSurface(const Surface& inner, std::shared_ptr<EvaluationBudget> budget,
                                 SurfacePtr owner)
    : Surface(inner.name(), inner.box()),
      inner_(inner),
      owner_(std::move(owner)),
      budget_(std::move(budget)) {}

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
