#pragma once
// One face of max(s, o) for two smooth solids: a mesh of s = 0 trimmed to where o < 0 and joined to the
// crease loops (crease_loops.hpp) by a band of triangles, then the surface-bound clean-up on s with the
// loops held, so that the face across (o = 0 where s < 0) shares the crease's vertices exactly. The
// face keeps any genus: it is trimmed, never cut into discs (docs/lattices.md).

#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <vector>

#include "api/crease_loops.hpp"

namespace isopatch {

/// The face of s = 0 where o < 0, from `mesh` (a mesh of s = 0, triangles along grad s, covering the
/// face and beyond it): vertices within about half an `edge` of o = 0 and beyond are dropped, each
/// boundary loop left is joined to the crease loop beside it, a crease loop with no boundary beside it (a
/// face smaller than an edge) is closed by a fan, and the whole face is cleaned up on s (`settings`'
/// preset and sizes over `box`) with the loops held bit for bit. `reversed`: the loops run against this
/// face's boundary direction (the face on o, whose side is on the right of grad s x grad o). The result's
/// first vertices are the loops' points, in loop order; its triangles run along grad s.
/// \throw CreaseError naming the place when a boundary loop has no crease beside it or two share one
///        (the face narrower than an edge there); the errors of remesh_on_surface().
Mesh zip_face_to_creases(const Mesh& mesh, const Surface& s, const Surface& o,
                         const std::vector<CreaseLoop>& loops, bool reversed, double edge,
                         const Settings& settings, const Box& box);

}  // namespace isopatch
