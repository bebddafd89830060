#pragma once
// The evaluation and time budget of BudgetSettings as one counter that every evaluation charges: once
// the count or the elapsed time passes its limit, the next charge throws LimitError naming the budget.
// Shared by BudgetedSurface (one surface) and BudgetedComposite (every patch function of a composite).
// Thread-safe.

#include <atomic>
#include <chrono>
#include <cstdint>

namespace isopatch {

class EvaluationBudget {
 public:
  /// \param max_evaluations  0: no limit
  /// \param seconds          0: no limit; counted from construction
  EvaluationBudget(std::uint64_t max_evaluations, double seconds);

  /// Counts n evaluations. \throw LimitError("...", "max_evaluations") when the count passes the
  /// limit, LimitError("...", "time_limit") when the time has (the clock is read every 256 evaluations:
  /// cheap, and at most a few microseconds late).
  void charge(std::uint64_t n);
  std::uint64_t evaluations() const { return count_.load(std::memory_order_relaxed); }

 private:
  std::uint64_t max_evaluations_;
  double seconds_;
  std::chrono::steady_clock::time_point start_;
  std::atomic<std::uint64_t> count_{0};
};

}  // namespace isopatch
