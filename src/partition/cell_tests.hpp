#pragma once
/// \file cell_tests.hpp
/// The sample-based single-sheet tests of docs/algorithms.md 2.9 (edge, face and normal-cone tests) and
/// the Newell normal used to check loop orientation (2.9.4), as pure functions of the samples.

#include <isopatch/geometry.hpp>

#include <span>

namespace isopatch {

/// Number of sign changes along first, interior..., last under the sign rule (f >= 0 positive).
int sign_changes(double first, std::span<const double> interior, double last);

/// Face test (docs/algorithms.md 2.9.2): project every gradient onto the plane with normal `axis` and require
/// all pairwise dot products of the projections to be strictly positive, i.e. f restricted to the face
/// is monotone along some in-plane direction at the samples. False when a projection vanishes or a
/// gradient is not finite.
bool in_plane_gradients_agree(std::span<const Vec3> gradients, int axis);

/// Normal-cone test (docs/algorithms.md 2.9.3): true when every gradient is finite and nonzero and the angle
/// between its direction and the normalized mean of the unit gradients is at most acos(cos_max).
/// \pre cos_max in [0, 1].
bool gradients_within_cone(std::span<const Vec3> gradients, double cos_max);

/// Newell's normal of a closed polygon, sum_k (Q_k - m) x (Q_{k+1} - m) with m the centroid: twice the
/// vector area, pointing so that the polygon is counter-clockwise about it.
Vec3 newell_normal(std::span<const Vec3> points);

}  // namespace isopatch
