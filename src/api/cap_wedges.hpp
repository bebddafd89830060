#pragma once
// Narrow corners of a planar cap: where the cut meets a polyhedron edge at a small angle (45 degrees
// where a gyroid crosses the edge of its box), a cap whose corner holds two or more triangles splits
// that angle and leaves triangles of half of it. The corner gets one triangle and the free vertices
// around it are relaxed in the plane.

#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>

#include <vector>

namespace isopatch {

/// In `cap` (a planar mesh, triangles counter-clockwise about `normal`), at every boundary vertex
/// (`held`) whose triangles span less than `narrow_degrees`, flips the inner edges at it while the
/// quadrilateral across each is convex, until one triangle is left there; then moves each free vertex
/// that lost such an edge towards the centroid of its neighbours where that raises the smallest angle
/// of its triangles. Held vertices never move; no triangle turns over.
void open_narrow_corners(Mesh& cap, const std::vector<bool>& held, const Vec3& normal, double narrow_degrees);

}  // namespace isopatch
