#pragma once
// A closed loop of points on f = 0 with no mesh beside it, filled by triangles (tile_seam.hpp): the
// cap of a tile's surface where its own mesh has no part.

#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace isopatch::blocks {

/// Whether triangle (a, b, c) faces along the gradients of f at its corners as the refinement's guard
/// asks (refine/lattice_relaxation.hpp faces_the_surface: within about 72 degrees of each).
bool faces_along(const Vec3& a, const Vec3& b, const Vec3& c, const std::array<Vec3, 3>& gradients);

/// Adds to `out` triangles that fill the loop of its vertices `loop` (at least three), oriented along
/// grad f: of the triangulations of the loop whose every triangle faces along grad f, the one whose
/// smallest angle is largest (dynamic programming, after Liepa 2003); for a loop of more than 160
/// points, or one no triangulation of which faces right, a fan around its centre put on f = 0 instead.
/// May reverse `loop`. The clean-up that follows splits the long inner edges. Returns false when it
/// made the fan.
/// \throw EvaluationError where f or grad f is not finite at the centre.
bool fill_loop(const Surface& surface, std::vector<std::uint32_t>& loop, Mesh& out);

}  // namespace isopatch::blocks
