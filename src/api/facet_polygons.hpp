#pragma once
// The faces of a convex polyhedron given by its planes: for each plane, the convex polygon where it
// bounds the polyhedron, each side labelled with the plane across it (Sutherland & Hodgman 1974,
// "Reentrant polygon clipping", a square of the plane clipped by every other plane).

#include <isopatch/convex_region.hpp>
#include <isopatch/geometry.hpp>

#include <vector>

namespace isopatch {

/// One face of the polyhedron: corners counter-clockwise about the plane's normal; side k runs from
/// corner k to corner k + 1 and lies on plane `across[k]`.
struct FacetPolygon {
  std::vector<Vec3> corners;
  std::vector<int> across;
};

/// a x + b y + c z + d at p: the plane's signed distance for a unit normal.
double plane_value(const HalfSpace& h, const Vec3& p);

/// The faces of the polyhedron of `planes` (unit normals) inside `box`: one entry per plane, with no
/// corners where the plane bounds no face of positive area (a redundant plane). Sides on the box's
/// faces are labelled -1: the polyhedron reaches the box there.
std::vector<FacetPolygon> facet_polygons(const ConvexRegion& planes, const Box& box);

}  // namespace isopatch
