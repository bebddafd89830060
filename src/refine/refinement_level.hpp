#pragma once
// Choosing the refinement level k from the surface's curvature: a base of edge length H = k h resolves
// the surface where the normal turns little across a base edge, H kappa <= max_turn (radians), kappa
// the largest principal curvature. Beyond that the projection distorts the base triangles (small angles
// on genus2 and chmutov6 at k = 8 in the prototype of docs/algorithms.md 8) or lands on another part of
// the surface.

#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <span>

namespace isopatch::refine {

/// The largest |principal curvature| of f = 0 at `points` (exact, from the Hessian; 0 for no points).
/// Parallel; the same value for any thread count. Infinite where grad f vanishes (a singular point);
/// where f or its derivatives are undefined it throws EvaluationError. With `skip_undefined`, points
/// where it is not finite are left out instead.
double largest_curvature(std::span<const Vec3> points, const Surface& surface, bool skip_undefined = false);

/// The largest k in [1, max_level] with k * edge * kappa <= max_turn (max_level when kappa is 0).
/// \pre edge > 0, max_turn > 0, max_level >= 1.
int level_for_curvature(double kappa, double edge, double max_turn, int max_level);

}  // namespace isopatch::refine
