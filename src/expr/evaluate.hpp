#pragma once
// The evaluators of a tape. They share nothing but the (immutable) tape; scratch registers live on
// the stack or in thread-local buffers, so every function is safe to call from many threads and
// allocates nothing once a thread has seen the tape size.

#include "expr/tape.hpp"

#include <isopatch/derivatives.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/interval.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace isopatch::expr {

/// Batch block length: registers hold this many points in structure-of-arrays form.
inline constexpr std::size_t kBlock = 256;

double evaluate(const Tape& tape, const Vec3& p);
ValueGradient evaluate_gradient(const Tape& tape, const Vec3& p);
SecondOrder evaluate_second_order(const Tape& tape, const Vec3& p);

void evaluate_batch(const Tape& tape, const double* x, const double* y, const double* z, double* out,
                    std::size_t n);
void evaluate_batch(const Tape& tape, std::span<const Vec3> points, std::span<double> out);

Interval evaluate_interval(const Tape& tape, const Box& box);
IntervalGradient evaluate_interval_gradient(const Tape& tape, const Box& box);
IntervalHessian evaluate_interval_hessian(const Tape& tape, const Box& box);

/// An enclosure of f over the box, as evaluate_interval(), with the branch every min, max and abs
/// instruction takes at all points of the box: decided[i] is 0 or 1 as switch_values() numbers the
/// branches (branches.hpp), or -1 where points of the box may take either (and for instructions that
/// are no switch). Sound for the computed values, ties included (interval_math.hpp).
/// \post decided.size() == tape.code.size().
Interval evaluate_interval_branches(const Tape& tape, const Box& box, std::vector<std::int8_t>& decided);

}  // namespace isopatch::expr
