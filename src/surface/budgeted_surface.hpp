#pragma once
// A Surface that forwards to another and enforces Settings' evaluation and time budgets: every
// evaluation (value, gradient, Hessian, interval bound) is counted, and once the count or the elapsed
// time passes its limit the next evaluation throws LimitError. Every mesher evaluates f as it works, so
// no run can go on past its budget, whatever loop it is in. Several surfaces may charge one budget (the
// patch functions and bounds of a composite, budgeted_composite.hpp). Thread-safe.

#include <isopatch/surface.hpp>

#include <cstdint>
#include <memory>

#include "surface/evaluation_budget.hpp"

namespace isopatch {

class BudgetedSurface final : public Surface {
 public:
  /// \param max_evaluations  0: no limit
  /// \param seconds          0: no limit; counted from construction
  BudgetedSurface(const Surface& inner, std::uint64_t max_evaluations, double seconds);
  /// Charges `budget`, shared with other surfaces; `owner` (may be null) keeps `inner` alive.
  BudgetedSurface(const Surface& inner, std::shared_ptr<EvaluationBudget> budget, SurfacePtr owner = nullptr);

  double value(const Vec3& p) const override;
  void values(std::span<const Vec3> points, std::span<double> out) const override;
  ValueGradient value_gradient(const Vec3& p) const override;
  void value_gradients(std::span<const Vec3> points, std::span<ValueGradient> out) const override;
  SecondOrder second_order(const Vec3& p) const override;
  std::optional<Interval> bound(const Box& box) const override;
  std::optional<IntervalGradient> gradient_bound(const Box& box) const override;

  std::uint64_t evaluations() const { return budget_->evaluations(); }

 private:
  /// Counts n evaluations; throws LimitError when a budget is exhausted.
  void charge(std::uint64_t n) const { budget_->charge(n); }

  const Surface& inner_;
  SurfacePtr owner_;
  std::shared_ptr<EvaluationBudget> budget_;
};

}  // namespace isopatch
