// The evaluation and time budget (evaluation_budget.hpp).
#include "surface/evaluation_budget.hpp"

#include <isopatch/error.hpp>

#include <string>

namespace isopatch {

EvaluationBudget::EvaluationBudget(std::uint64_t max_evaluations, double seconds)
    : max_evaluations_(max_evaluations), seconds_(seconds), start_(std::chrono::steady_clock::now()) {}

void EvaluationBudget::charge(std::uint64_t n) {
  const std::uint64_t before = count_.fetch_add(n, std::memory_order_relaxed);
  const std::uint64_t after = before + n;
  if (max_evaluations_ > 0 && after > max_evaluations_)
    throw LimitError(
        "the evaluation budget of " + std::to_string(max_evaluations_) + " evaluations of f is exhausted",
        "max_evaluations");
  if (seconds_ > 0.0 && (before >> 8) != (after >> 8)) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed > seconds_)
      throw LimitError("the time limit of " + std::to_string(seconds_) + " s is exceeded", "time_limit");
  }
}

}  // namespace isopatch
