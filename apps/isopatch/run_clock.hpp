#pragma once
// The clock of one command as the user waits for it: from the process's start (as the system records it)
// through the stages the command itself runs around the mesher (reading the input, the searches before
// meshing, writing, the checks after it), so that the statistics account for every second of the run.

#include <isopatch/mesh_stats.hpp>

#include <chrono>
#include <string>

namespace isopatch::cli {

/// Seconds since this process started, from /proc/self/stat's start time and /proc/uptime (the
/// kernel's clock ticks, 10 ms on Linux); 0 when they cannot be read.
double process_age_seconds();

/// Stage times of a command: created at the command's start, it holds the process's age then (the
/// stage "startup": loading, parsing the command line) and times each later stage from the previous mark.
class RunClock {
 public:
  RunClock();

  /// The seconds since the previous mark (or the start), and a new mark.
  double lap();

  /// Seconds from the process's start to now.
  double total() const;

  /// Adds the command's stages to `stats.times`: "startup", each of `laps` already taken, the part of the
  /// mesher's own seconds its stages do not name ("meshing_other"), and "total" (total()).
  void account(MeshStats& stats) const;

  /// Records a stage: `seconds` under `name` (added to what it has).
  void add(const std::string& name, double seconds);

 private:
  std::chrono::steady_clock::time_point start_, mark_;
  double age_at_start_ = 0.0;
  StageTimes stages_;
};

}  // namespace isopatch::cli
