#pragma once
/// \file convex_cell_tests.hpp
/// The single-sheet tests of docs/algorithms.md 2.9 for general convex cells (convex_partition.hpp),
/// where faces have any normal: the face test with gradients projected onto the face's plane, and the
/// interval certificate of the edge test along a segment of any direction.

#include <isopatch/surface.hpp>

#include <span>

namespace isopatch {

/// Face test (docs/algorithms.md 2.9.2) on a face with unit normal `normal`: the gradients projected onto
/// its plane pairwise have strictly positive dot products. False when a projection vanishes or a
/// gradient is not finite.
bool in_plane_gradients_agree(std::span<const Vec3> gradients, const Vec3& normal);

/// Whether f is monotone along the segment from a to b by its gradient bound over the segment's bounds
/// (the interval of (b - a) . grad f excludes 0): the segment then changes sign at most once, and the
/// edge test needs no samples. False when the surface gives no bound.
bool segment_monotone_by_interval(const Surface& surface, const Vec3& a, const Vec3& b);

}  // namespace isopatch
