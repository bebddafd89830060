#pragma once
// A copy of a composite whose patch functions and bounds all charge one evaluation and time budget
// (BudgetSettings), so that the composite mesher, like every other, cannot run past its budget,
// whichever patch it is working on. Thread-safe.

#include <cstdint>
#include <memory>

#include "api/evaluation_budget.hpp"
#include "ipatch/composite.hpp"

namespace isopatch {

class BudgetedComposite {
 public:
  /// \param max_evaluations  0: no limit
  /// \param seconds          0: no limit; counted from construction
  BudgetedComposite(const Composite& composite, std::uint64_t max_evaluations, double seconds);
  const Composite& composite() const { return composite_; }

  /// The shared budget (public for the forwarding surfaces of budgeted_composite.cpp).
  using Budget = EvaluationBudget;

 private:
  std::shared_ptr<Budget> budget_;
  Composite composite_;
};

}  // namespace isopatch
