// A composite whose functions charge one budget (budgeted_composite.hpp).
#include "composite_model/budgeted_composite.hpp"

#include "surface/budgeted_surface.hpp"

#include <isopatch/error.hpp>
#include <isopatch/surface.hpp>

#include <string>
#include <utility>

namespace isopatch {

BudgetedComposite::BudgetedComposite(const Composite& composite, std::uint64_t max_evaluations,
                                     double seconds)
    : budget_(std::make_shared<EvaluationBudget>(max_evaluations, seconds)), composite_(composite) {
  const auto charged = [this](const SurfacePtr& s) -> SurfacePtr {
    return s ? std::make_shared<BudgetedSurface>(*s, budget_, s) : s;
  };
  for (CompositePatch& p : composite_.patches) {
    p.surface = charged(p.surface);
    for (SurfacePtr& b : p.bounds) b = charged(b);
  }
}

}  // namespace isopatch
