#pragma once
// A bracketed scalar root finder shared by every mesher: the Illinois variant of regula falsi
// (Dowell & Jarratt 1971) with a bisection safeguard. Illinois halves the value kept at a stagnant end,
// which restores superlinear convergence where plain regula falsi crawls; bisection whenever two steps
// did not halve the bracket bounds the worst case to plain bisection.

#include <algorithm>
#include <cmath>
#include <limits>

namespace isopatch {

/// The root finder as a state machine, for callers that evaluate phi in batches (many roots at once,
/// one evaluation of each per round): next() is the point to evaluate, feed() takes phi there. It makes
/// exactly the evaluations and returns exactly the result of bracketed_root() below, which runs it.
class BracketedRoot {
 public:
  /// The bracket [a, b] with fa = phi(a) and fb = phi(b) of opposite signs under the sign rule; the
  /// stopping rules of bracketed_root().
  BracketedRoot(double a, double fa, double b, double fb, double tolerance, int max_iterations = 100)
      : tolerance_(tolerance), max_iterations_(max_iterations) {
    if (fa == 0.0 || fb == 0.0) {
      done_ = true;
      result_ = fa == 0.0 ? a : b;
      return;
    }
    t_neg_ = fa < 0.0 ? a : b, g_neg_ = fa < 0.0 ? fa : fb;
    t_pos_ = fa < 0.0 ? b : a, g_pos_ = fa < 0.0 ? fb : fa;
    true_neg_ = g_neg_, true_pos_ = g_pos_;
    advance();
  }

  /// Whether the root is found (result() is then final).
  bool done() const { return done_; }
  /// The point where phi is wanted next. \pre !done().
  double next() const { return pending_; }
  /// phi(next()). \pre !done().
  void feed(double g) {
    ++step_;
    if (g == 0.0) {
      done_ = true;
      result_ = pending_;
      return;
    }
    if (g < 0.0) {
      t_neg_ = pending_;
      g_neg_ = true_neg_ = g;
      if (last_moved_ == -1) g_pos_ *= 0.5;
      last_moved_ = -1;
    } else {
      t_pos_ = pending_;
      g_pos_ = true_pos_ = g;
      if (last_moved_ == +1) g_neg_ *= 0.5;
      last_moved_ = +1;
    }
    advance();
  }
  /// The end of the final bracket with the smaller |phi| (or the point where phi is exactly 0).
  /// \pre done().
  double result() const { return result_; }

 private:
  /// The next point to evaluate, or done when a stopping rule holds.
  void advance() {
    if (step_ >= max_iterations_) return finish();
    const double width = std::abs(t_pos_ - t_neg_);
    if (width <= tolerance_) return finish();
    const double lo = std::min(t_neg_, t_pos_), hi = std::max(t_neg_, t_pos_);
    double t = t_neg_ - g_neg_ * (t_pos_ - t_neg_) / (g_pos_ - g_neg_);
    if (!(t > lo && t < hi) || width > 0.5 * width_before_last_) t = 0.5 * (lo + hi);
    if (!(t > lo && t < hi)) return finish();  // adjacent doubles
    width_before_last_ = width_last_;
    width_last_ = width;
    pending_ = t;
  }
  void finish() {
    done_ = true;
    result_ = std::abs(true_neg_) < std::abs(true_pos_) ? t_neg_ : t_pos_;
  }

  double tolerance_;
  int max_iterations_;
  int step_ = 0;
  bool done_ = false;
  double result_ = 0.0, pending_ = 0.0;
  double t_neg_ = 0.0, g_neg_ = 0.0, t_pos_ = 0.0, g_pos_ = 0.0;
  double true_neg_ = 0.0, true_pos_ = 0.0;  // unhalved values, to pick the better end
  int last_moved_ = 0;                      // -1: the negative end moved last, +1: the positive end
  double width_last_ = std::numeric_limits<double>::infinity();
  double width_before_last_ = std::numeric_limits<double>::infinity();
};

/// Finds t between a and b with phi(t) = 0, given fa = phi(a) and fb = phi(b) of opposite signs under
/// the sign rule (v >= 0 positive). Stops when the bracket is at most `tolerance` wide, phi is exactly 0,
/// the bracket is down to adjacent doubles, or after `max_iterations` evaluations. Returns the end of
/// the final bracket with the smaller |phi| (an end whose value is exactly 0 is returned as is).
template <class Phi>
double bracketed_root(Phi&& phi, double a, double fa, double b, double fb, double tolerance,
                      int max_iterations = 100) {
  BracketedRoot root(a, fa, b, fb, tolerance, max_iterations);
  while (!root.done()) root.feed(phi(root.next()));
  return root.result();
}

}  // namespace isopatch
