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

/// How the box cuts the part: not at all (the face's mesh is closed where o < 0), or open on the box's
/// faces, the trimmed face joined to its boundary there where it reaches it (`Runs`) or its whole ring
/// at the box joined anew (`Ring`).
enum class BoxCut { None, Runs, Ring };

/// The face of s = 0 where o < 0, from `mesh` (a mesh of s = 0, triangles along grad s, covering the
/// face and beyond it): vertices within 0.3 `edge` of o = 0 (0.15, then 0.05 where that fails) and beyond
/// are dropped, with the thin tails and pieces lying within 1.5 edges of it throughout (then only the
/// pieces, then none); the boundary loops left are walked to the crease loops (band_join.hpp); a crease
/// loop no walk or strip reached, within two edges of its centroid, is closed by a fan; the band is
/// cleaned up on s (`settings`' preset and sizes over `box`) with the loops held bit for bit, or the
/// whole face when `whole` (a mesh finer than `edge`, brought to it). Where the box cuts the face (`loops`
/// ends with open arcs, after the closed loops; `mesh` open on the box's faces), the mesh's own boundary
/// stays boundary and each run of the trimmed boundary from the box to the box is joined to the arc beside
/// it (band_join.hpp join_open_runs). `reversed`: the loops run against
/// this face's boundary direction (the face on o, whose side is on the right of grad s x grad o). The
/// result's first vertices are the loops' points, in loop order; its triangles run along grad s.
/// \throw CreaseError naming the place when no trim joins (creases closer than the band, branching
///        strips); EvaluationError where o is not finite; the errors of remesh_on_surface().
Mesh zip_face_to_creases(const Mesh& mesh, const Surface& s, const Surface& o,
                         const std::vector<CreaseLoop>& loops, bool reversed, double edge,
                         const Settings& settings, const Box& box, bool whole = false,
                         BoxCut cut = BoxCut::None);

}  // namespace isopatch
