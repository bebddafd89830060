// The clock of one command from the process's start (run_clock.hpp).
#include "run_clock.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace isopatch::cli {

double process_age_seconds() {
  // Field 22 of /proc/self/stat is the start time in clock ticks after boot; the command name (field 2)
  // may hold spaces, so the fields are counted after its last closing parenthesis.
  char stat[1024] = {};
  double uptime = 0.0;
  std::FILE* f = std::fopen("/proc/self/stat", "r");
  const std::size_t n = f ? std::fread(stat, 1, sizeof stat - 1, f) : 0;
  if (f) std::fclose(f);
  char uptime_text[64] = {};
  std::FILE* u = std::fopen("/proc/uptime", "r");
  const std::size_t m = u ? std::fread(uptime_text, 1, sizeof uptime_text - 1, u) : 0;
  if (u) std::fclose(u);
  char* uptime_end = nullptr;
  uptime = m > 0 ? std::strtod(uptime_text, &uptime_end) : 0.0;
  const bool have_uptime = uptime_end != nullptr && uptime_end != uptime_text;
  const long ticks = sysconf(_SC_CLK_TCK);
  const char* close = n > 0 ? std::strrchr(stat, ')') : nullptr;
  if (!close || !have_uptime || ticks <= 0) return 0.0;
  const char* p = close + 1;
  for (int field = 3; field < 22 && *p; ++field) {
    while (*p == ' ') ++p;
    while (*p && *p != ' ') ++p;
  }
  char* end = nullptr;
  const double started = std::strtod(p, &end);
  if (end == p) return 0.0;
  return std::max(0.0, uptime - started / static_cast<double>(ticks));
}

RunClock::RunClock()
    : start_(std::chrono::steady_clock::now()), mark_(start_), age_at_start_(process_age_seconds()) {}

double RunClock::lap() {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - mark_).count();
  mark_ = now;
  return seconds;
}

double RunClock::total() const {
  return age_at_start_ + std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void RunClock::add(const std::string& name, double seconds) {
  stages_.add(name, seconds);
}

void RunClock::account(MeshStats& stats) const {
  double named = 0.0;
  for (const auto& [stage, seconds] : stats.times.seconds) named += seconds;
  StageTimes times;
  times.add("startup", age_at_start_);
  times.merge(stages_);
  times.merge(stats.times);
  times.add("meshing_other", std::max(0.0, stats.seconds - named));
  times.add("total", total());
  stats.times = times;
}

}  // namespace isopatch::cli
