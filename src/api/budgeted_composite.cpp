// A composite whose functions charge one budget (budgeted_composite.hpp).
#include "api/budgeted_composite.hpp"

#include <isopatch/error.hpp>
#include <isopatch/surface.hpp>

#include <string>
#include <utility>

namespace isopatch {

namespace {

/// Forwards to a surface after charging the shared budget.
class ChargedSurface final : public Surface {
 public:
  ChargedSurface(SurfacePtr inner, std::shared_ptr<BudgetedComposite::Budget> budget)
      : Surface(inner->name(), inner->box()), inner_(std::move(inner)), budget_(std::move(budget)) {}
  double value(const Vec3& p) const override {
    budget_->charge(1);
    return inner_->value(p);
  }
  void values(std::span<const Vec3> points, std::span<double> out) const override {
    budget_->charge(points.size());
    inner_->values(points, out);
  }
  ValueGradient value_gradient(const Vec3& p) const override {
    budget_->charge(1);
    return inner_->value_gradient(p);
  }
  SecondOrder second_order(const Vec3& p) const override {
    budget_->charge(1);
    return inner_->second_order(p);
  }
  std::optional<Interval> bound(const Box& box) const override {
    budget_->charge(1);
    return inner_->bound(box);
  }
  std::optional<IntervalGradient> gradient_bound(const Box& box) const override {
    budget_->charge(1);
    return inner_->gradient_bound(box);
  }

 private:
  SurfacePtr inner_;
  std::shared_ptr<BudgetedComposite::Budget> budget_;
};

}  // namespace

BudgetedComposite::BudgetedComposite(const Composite& composite, std::uint64_t max_evaluations,
                                     double seconds)
    : budget_(std::make_shared<Budget>(max_evaluations, seconds)), composite_(composite) {
  const auto charged = [this](const SurfacePtr& s) -> SurfacePtr {
    return s ? std::make_shared<ChargedSurface>(s, budget_) : s;
  };
  for (CompositePatch& p : composite_.patches) {
    p.surface = charged(p.surface);
    for (SurfacePtr& b : p.bounds) b = charged(b);
  }
}

}  // namespace isopatch
