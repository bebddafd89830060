// Tangential relaxation of the surface-bound clean-up (one run's state: remesh_run.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "remesh/remesh_run.hpp"

namespace isopatch::cleanup {

/// Tangential relaxation towards the area-weighted centroid of the incident triangles, then back onto
/// f = 0 (Gauss-Seidel order; a move that would fold a triangle or leave the box is skipped).
void relax(RemeshRun& run, int rounds = 1);

/// `rounds` of relax_vertex over `vertices`, by classes of non-adjacent vertices (a move reads only
/// its neighbours), each class in parallel: the same result for any number of threads.
void relax(RemeshRun& run, const std::vector<std::uint32_t>& vertices, int rounds);

/// Moves v towards the area-weighted centroid of its triangles, tangentially, then onto f = 0; a
/// sliding cut vertex along its box face. Writes only v. False when the move was refused.
bool relax_vertex(RemeshRun& run, std::uint32_t v);

/// Moves a boundary vertex that may slide towards the midpoint of its two boundary neighbours, then
/// onto the curve where f = 0 meets its box face or region plane (it stays on it and off the others).
bool relax_along_box_face(RemeshRun& run, std::uint32_t v);

/// Moves boundary vertex v to q with the normal of `gradient` when none of its triangles folds; false
/// when one would.
bool move_boundary_vertex(RemeshRun& run, std::uint32_t v, const Vec3& q, const Vec3& gradient);

}  // namespace isopatch::cleanup
