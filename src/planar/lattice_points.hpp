#pragma once
// Interior points of a planar region on the equilateral triangular lattice: the vertices of a cap
// whose every inner vertex has valence 6 by construction, away from its boundary.

#include <vector>

#include "planar/planar_region.hpp"

namespace isopatch::planar {

/// The points of the triangular lattice of spacing `spacing` (rows along x, one point at the lower
/// left corner of the region's bounds) that lie inside `region` (winding number > 0 about its
/// segments) at a distance of at least `clearance` from every segment, row by row in increasing x.
/// Deterministic: the same region gives the same points.
/// \pre spacing > 0, clearance >= 0; the caller bounds the count (area / spacing^2).
std::vector<Vec2> interior_lattice_points(const Region& region, double spacing, double clearance);

}  // namespace isopatch::planar
