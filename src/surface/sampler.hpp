#pragma once
// A checked, counting view of a Surface for the meshers: every evaluation is counted (for statistics
// and benchmarks) and every non-finite result raises EvaluationError naming the point. Thread-safe.

#include <isopatch/surface.hpp>

#include <atomic>
#include <cstdint>

namespace isopatch {

class Sampler {
 public:
  explicit Sampler(const Surface& surface) : surface_(surface) {}

  /// f(p). \throw EvaluationError if f(p) is NaN or infinite.
  double value(const Vec3& p) const;
  /// f(p) and grad f(p). \throw EvaluationError if either is not finite.
  ValueGradient value_gradient(const Vec3& p) const;
  /// f(p) and grad f(p), counted but not checked: either may be NaN or infinite.
  ValueGradient value_gradient_unchecked(const Vec3& p) const;

  const Surface& surface() const { return surface_; }
  std::uint64_t value_count() const { return values_.load(std::memory_order_relaxed); }
  std::uint64_t gradient_count() const { return gradients_.load(std::memory_order_relaxed); }

 private:
  const Surface& surface_;
  mutable std::atomic<std::uint64_t> values_{0};
  mutable std::atomic<std::uint64_t> gradients_{0};
};

/// "f is NaN at (x, y, z)" style message, shared by every place that checks values.
[[noreturn]] void throw_not_finite(const char* what, double value, const Vec3& p);

}  // namespace isopatch
