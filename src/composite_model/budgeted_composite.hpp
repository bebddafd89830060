#pragma once
// A copy of a composite whose patch functions and bounds all charge one evaluation and time budget
// (BudgetSettings), so that the composite mesher, like every other, cannot run past its budget,
// whichever patch it is working on: each function wrapped in a BudgetedSurface charging one shared
// EvaluationBudget. Thread-safe.

#include <cstdint>
#include <memory>

#include "composite_model/composite.hpp"
#include "surface/evaluation_budget.hpp"

namespace isopatch {

class BudgetedComposite {
 public:
  /// \param max_evaluations  0: no limit
  /// \param seconds          0: no limit; counted from construction
  BudgetedComposite(const Composite& composite, std::uint64_t max_evaluations, double seconds);
  const Composite& composite() const { return composite_; }

 private:
  std::shared_ptr<EvaluationBudget> budget_;
  Composite composite_;
};

}  // namespace isopatch
