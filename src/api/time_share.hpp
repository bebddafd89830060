#pragma once
// One time limit shared by the stages of a run (BudgetSettings::time_limit): a run tries several paths
// one after the other (a sheet's walls, caps, a curved cut, the crease analysis, a cut-open shape, the
// smooth mesher), each of which charges only its own evaluations; every stage gets what the earlier ones
// left, and none starts once the limit is spent.

#include <isopatch/error.hpp>
#include <isopatch/settings.hpp>

#include <chrono>
#include <string>

namespace isopatch {

class TimeShare {
 public:
  /// Starts the clock for `settings` (kept by reference: it must outlive the share).
  explicit TimeShare(const Settings& settings)
      : settings_(settings), start_(std::chrono::steady_clock::now()) {}

  /// The settings for the next stage: time_limit set to what is left (unchanged without a limit).
  /// \throw LimitError("time_limit") once the limit is spent, in the words of the evaluation budget.
  Settings next() const {
    Settings s = settings_;
    if (settings_.time_limit > 0.0) {
      const double used = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      if (used >= settings_.time_limit)
        throw LimitError("the time limit of " + std::to_string(settings_.time_limit) + " s is exceeded",
                         "time_limit");
      s.time_limit = settings_.time_limit - used;
    }
    return s;
  }

 private:
  const Settings& settings_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace isopatch
