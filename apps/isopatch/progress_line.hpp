#pragma once
// A single updating status line on stderr for long runs of `isopatch mesh`: each update overwrites the
// previous one ("\r"), at most ten times per second, and the line is ended with a newline when the run
// finishes or fails (so an error message starts on a line of its own).

#include <isopatch/settings.hpp>

#include <chrono>
#include <cstdio>
#include <string>

namespace isopatch::cli {

class ProgressLine {
 public:
  /// \param out    the stream to draw on (stderr)
  /// \param label  what runs, e.g. "mc" or "projection"
  /// \param unit   what Progress counts for that method, e.g. "slabs" or "rounds"
  ProgressLine(std::FILE* out, std::string label, std::string unit);
  /// Calls finish().
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// Records `p`; redraws the line unless the last drawing is less than 0.1 s old (the first update is
  /// always drawn).
  void update(const Progress& p);
  /// Draws the latest update if it was not drawn yet, then ends the line with "\n". Does nothing when
  /// no update came or when already finished.
  void finish();

 private:
  void draw();

  std::FILE* out_;
  std::string label_;
  std::string unit_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  Progress latest_;
  bool updated_ = false;  ///< an update came
  bool drawn_ = false;    ///< latest_ is on screen
  bool finished_ = false;
  std::size_t width_ = 0;  ///< length of the text on screen, to blank a longer previous one
};

/// Whether `isopatch mesh` shows progress: always with --progress (`forced`), otherwise only when
/// stderr is a terminal and --quiet is not given.
bool progress_wanted(bool forced, bool quiet);

}  // namespace isopatch::cli
