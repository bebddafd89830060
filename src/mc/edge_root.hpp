#pragma once
// Sampling helpers of the marching cubes mesher: checked evaluation of f and the crossing of f = 0 on
// one grid edge.

#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <cstdint>

namespace isopatch::mc {

/// Throws EvaluationError("f is NaN at (x, y, z)") (or "inf") unless `value` is finite.
void check_value(double value, const Vec3& p);

/// f(p), checked by check_value(); increments `evaluations`.
double checked_value(const Surface& surface, const Vec3& p, std::uint64_t& evaluations);

/// The point where f changes sign on the segment [a, b], given fa = f(a) and fb = f(b) of opposite
/// signs under the rule "f >= 0 is positive" (exactly one of them is < 0).
/// EdgeRoot::Linear interpolates fa and fb linearly. EdgeRoot::Bracketed runs the Illinois variant of
/// regula falsi (Dowell & Jarratt 1971) with a bisection safeguard until the bracket is at most 1e-13
/// of the segment, f is exactly 0, or 100 steps were taken; every f evaluation is counted and checked.
/// The result lies on [a, b]; it is b (or a) exactly when that end's value is 0.
Vec3 edge_root(const Surface& surface, const Vec3& a, const Vec3& b, double fa, double fb, EdgeRoot mode,
               std::uint64_t& evaluations);

}  // namespace isopatch::mc
