#pragma once
// A checked, counting view of a Surface for the meshers: every evaluation is counted (for statistics
// and benchmarks) and every non-finite result raises EvaluationError naming the point. Thread-safe.

#include <isopatch/surface.hpp>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>

namespace isopatch {

/// An event count that many threads raise at once without sharing a cache line: one padded slot per
/// worker of the current TBB arena (beyond kSlots workers, slots are shared, still exactly). The total
/// is exact once the counting threads are done (every increment is atomic), whatever the thread count.
/// One shared atomic instead cost the clean-up's relaxation all of its speed-up on two threads.
class SpreadCounter {
 public:
  /// Adds `count` (1 by default). Thread-safe.
  void add(std::uint64_t count = 1) const;
  /// The sum of every add() that happened before (relaxed reads of each slot).
  std::uint64_t total() const;

 private:
  static constexpr std::size_t kSlots = 64;
  struct alignas(64) Slot {
    std::atomic<std::uint64_t> count{0};
  };
  mutable std::array<Slot, kSlots> slots_{};
};

class Sampler {
 public:
  explicit Sampler(const Surface& surface) : surface_(surface) {}

  /// f(p). \throw EvaluationError if f(p) is NaN or infinite.
  double value(const Vec3& p) const;
  /// out[i] = f(points[i]) through Surface::values (one batch: the same values as value(), bit for
  /// bit, for the built-in evaluator; far cheaper per point). \pre out.size() == points.size().
  /// \throw EvaluationError naming the first point whose value is not finite.
  void values(std::span<const Vec3> points, std::span<double> out) const;
  /// f(p) and grad f(p). \throw EvaluationError if either is not finite.
  ValueGradient value_gradient(const Vec3& p) const;
  /// out[i] = value_gradient(points[i]) through Surface::value_gradients (one batch, the same numbers).
  /// \pre out.size() == points.size().
  /// \throw EvaluationError naming the first point whose value or gradient is not finite.
  void value_gradients(std::span<const Vec3> points, std::span<ValueGradient> out) const;
  /// f(p) and grad f(p), counted but not checked: either may be NaN or infinite.
  ValueGradient value_gradient_unchecked(const Vec3& p) const;

  const Surface& surface() const { return surface_; }
  std::uint64_t value_count() const { return values_.total(); }
  std::uint64_t gradient_count() const { return gradients_.total(); }

 private:
  const Surface& surface_;
  SpreadCounter values_;
  SpreadCounter gradients_;
};

/// "f is NaN at (x, y, z)" style message, shared by every place that checks values.
[[noreturn]] void throw_not_finite(const char* what, double value, const Vec3& p);

}  // namespace isopatch
