#include "progress_line.hpp"

#include <unistd.h>

#include <algorithm>
#include <utility>

namespace isopatch::cli {

namespace {
constexpr std::chrono::milliseconds kMinInterval{100};
}  // namespace

ProgressLine::ProgressLine(std::FILE* out, std::string label, std::string unit)
    : out_(out), label_(std::move(label)), unit_(std::move(unit)), start_(std::chrono::steady_clock::now()) {}

ProgressLine::~ProgressLine() {
  finish();
}

void ProgressLine::update(const Progress& p) {
  if (finished_) return;
  latest_ = p;
  updated_ = true;
  drawn_ = false;
  const auto now = std::chrono::steady_clock::now();
  if (width_ == 0 || now - last_draw_ >= kMinInterval) draw();
}

void ProgressLine::finish() {
  if (finished_ || !updated_) return;
  if (!drawn_) draw();
  std::fputc('\n', out_);
  std::fflush(out_);
  finished_ = true;
}

void ProgressLine::draw() {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start_).count();
  char text[160];
  const int n = latest_.stage
                    ? std::snprintf(text, sizeof text, "isopatch: %s %s %zu/%zu, %.1f s", label_.c_str(),
                                    latest_.stage, latest_.done, latest_.total, seconds)
                    : std::snprintf(text, sizeof text, "isopatch: %s %zu/%zu %s, %.1f s", label_.c_str(),
                                    latest_.done, latest_.total, unit_.c_str(), seconds);
  const std::size_t length = n < 0 ? 0 : std::min(static_cast<std::size_t>(n), sizeof text - 1);
  // Blank what a longer previous text left behind.
  const int pad = width_ > length ? static_cast<int>(width_ - length) : 0;
  std::fprintf(out_, "\r%s%*s", text, pad, "");
  std::fflush(out_);
  width_ = length;
  last_draw_ = now;
  drawn_ = true;
}

bool progress_wanted(bool forced, bool quiet) {
  return forced || (!quiet && ::isatty(STDERR_FILENO) == 1);
}

}  // namespace isopatch::cli
