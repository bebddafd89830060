#pragma once
/// \file interval.hpp
/// Closed intervals [lo, hi] of doubles for sound bounds of f and its gradient over a box.
/// An interval may be unbounded (lo = -inf or hi = +inf); `empty()` intervals have lo > hi.

#include <limits>

namespace isopatch {

struct Interval {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();

  bool contains(double v) const { return lo <= v && v <= hi; }
  bool contains_zero() const { return lo <= 0.0 && 0.0 <= hi; }
  /// Whether 0 lies outside [lo, hi] for certain: false when a bound is NaN (an interval evaluation
  /// that lost track of the value proves nothing), unlike !contains_zero().
  bool excludes_zero() const { return lo > 0.0 || hi < 0.0; }
  bool empty() const { return !(lo <= hi); }
  double width() const { return hi - lo; }
};

}  // namespace isopatch
