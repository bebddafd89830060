#pragma once
// A scope's wall time added to one stage of a StageTimes (mesh_stats.hpp); a null StageTimes is fine.

#include <isopatch/mesh_stats.hpp>

#include <chrono>

namespace isopatch {

class StageTimer {
 public:
  /// Starts timing `stage` (a literal: the name must outlive the timer) into `times` (may be null).
  StageTimer(StageTimes* times, const char* stage)
      : times_(times), stage_(stage), start_(std::chrono::steady_clock::now()) {}
  ~StageTimer() {
    if (times_)
      times_->add(stage_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  StageTimes* times_;
  const char* stage_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace isopatch
