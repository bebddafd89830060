#pragma once
// The constrained Delaunay triangulation of a planar region with points inside it (CGAL's
// Constrained_Delaunay_triangulation_2 with exact predicates: Chew 1989, "Constrained Delaunay
// triangulations"), its triangles inside the region kept by a walk across unconstrained edges.

#include <array>
#include <cstdint>
#include <vector>

#include "planar/planar_region.hpp"

namespace isopatch::planar {

/// Triangles (counter-clockwise) covering `region`, whose points are region.points followed by
/// `inner` (indices continue after region.points). Every segment of the region is an edge of exactly
/// one triangle, on its left.
/// \throw CreaseError with a one-line reason when two points coincide, a
///        segment crosses another or passes through a point, the loops do not close, or a segment's
///        left side is outside the region as the other segments bound it.
std::vector<std::array<std::uint32_t, 3>> triangulate_region(const Region& region,
                                                             const std::vector<Vec2>& inner);

}  // namespace isopatch::planar
