#pragma once
// Narrow corners at a held boundary: where the cut meets a polyhedron edge at a small angle (45 degrees
// where a gyroid crosses the edge of its box), a side whose corner holds two or more triangles splits
// that angle and leaves triangles of half of it. The corner gets one triangle and the free vertices
// around it are relaxed on their surface: a cap's plane, or the cut surface g = 0 itself.

#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <vector>

namespace isopatch {

/// In `mesh`, a mesh of `surface` (its triangles counter-clockwise about grad f), at every held vertex
/// (`held`: the boundary) whose triangles span less than `narrow_degrees`, flips the inner edges at it
/// while the quadrilateral across each is convex (about grad f there), until one triangle per 60
/// degrees of that span is left (at least one);
/// then moves each free vertex that lost such an edge towards the centroid of its neighbours, put back
/// on f = 0 to `tolerance`, where that raises the smallest angle of its triangles. Held vertices never
/// move; no triangle turns over.
/// 	hrow EvaluationError where f or grad f is not finite.
void open_narrow_corners(Mesh& mesh, const Surface& surface, const std::vector<bool>& held,
                         double narrow_degrees, double tolerance);

}  // namespace isopatch
