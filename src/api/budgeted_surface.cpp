// Evaluation and time budgets around a Surface (see budgeted_surface.hpp).
#include "api/budgeted_surface.hpp"

#include <isopatch/error.hpp>

#include <string>

namespace isopatch {

BudgetedSurface::BudgetedSurface(const Surface& inner, std::uint64_t max_evaluations, double seconds)
    : Surface(inner.name(), inner.box()),
      inner_(inner),
      max_evaluations_(max_evaluations),
      seconds_(seconds),
      start_(std::chrono::steady_clock::now()) {}

void BudgetedSurface::charge(std::uint64_t n) const {
  const std::uint64_t before = count_.fetch_add(n, std::memory_order_relaxed);
  const std::uint64_t after = before + n;
  if (max_evaluations_ > 0 && after > max_evaluations_)
    throw LimitError(
        "the evaluation budget of " + std::to_string(max_evaluations_) + " evaluations of f is exhausted",
        "max_evaluations");
  // The clock is read every 256 evaluations: cheap, and at most a few microseconds late.
  if (seconds_ > 0.0 && (before >> 8) != (after >> 8)) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed > seconds_)
      throw LimitError("the time limit of " + std::to_string(seconds_) + " s is exceeded", "time_limit");
  }
}

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
