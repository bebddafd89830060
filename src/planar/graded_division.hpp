#pragma once
// Dividing a segment into pieces whose lengths grade from the size wanted at one end to the size wanted
// at the other (a geometric progression: the size grows linearly along the segment), so that a cap's side
// between two short edges of the cut is sampled as finely as they are.

#include <vector>

namespace isopatch::planar {

/// The interior division points of a segment of `length` as fractions in (0, 1), increasing: n pieces,
/// n = the integral of 1 / s over the segment rounded (at least 1), where s grows linearly from
/// `size_a` at 0 to `size_b` at 1, and the k-th point where that integral reaches k / n of its whole.
/// Equal sizes give n equal pieces.
/// \pre length >= 0; size_a, size_b > 0 and finite.
std::vector<double> graded_division(double length, double size_a, double size_b);

}  // namespace isopatch::planar
