// The error bound (RemeshSizes::max_error) of the surface-bound clean-up (remesh_run.hpp).
#pragma once

#include <cstddef>

#include "remesh/remesh_run.hpp"

namespace isopatch::cleanup {

/// The size law takes the curvature of one point and the edges' spread from the grading, so where the
/// curvature changes within an edge (the rounded edges of x^16 + y^16 + z^16 = 1) a triangle's centroid
/// can end up beyond the bound. Splits the longest edge of each triangle beyond kBoundMargin * EPS
/// (longest first), the new vertex projected onto f = 0, until none is left or kBoundRounds rounds
/// pass; the small-angle repair follows each round (relaxation would bend the new vertices back:
/// x^16 + y^16 + z^16 = 1 at EPS 0.0012 stayed at 1.09 EPS with it, 0.89 EPS without). Each round
/// evaluates f once per triangle. Returns the triangles beyond EPS after the last change: where the
/// partition cut a thin tip short, the splits there make triangles whose normals leave their vertices'
/// and are refused (a needle 1:0.05:0.05 along the diagonal).
std::size_t enforce_error_bound(RemeshRun& run);

}  // namespace isopatch::cleanup
