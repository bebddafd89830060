#pragma once
// Two smooth solids capped by axis-aligned planes, f = max(a, b, p_1, ..., p_k) (csg/capped_shape.hpp
// CappedCutShape): a lattice inside a cylinder capped at both ends, a sheet inside a ball cut flat. The
// planes bound a box; a and b are meshed as two solids intersected in it (curved_cut.hpp), which leaves
// the part open exactly on its faces with the crease running in arcs from face to face, and the faces
// that are the part's planes are closed by planar caps (planar_caps.hpp): the region where max(a, b) < 0
// on each, bounded by the part's own boundary there and the pieces of the polygon's sides inside the
// solid. Neither face is ever cut into discs, whatever its genus. docs/lattices.md.

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <optional>

namespace isopatch {

/// The mesh of `surface` as two smooth solids capped by axis-aligned planes, or nullopt when it is not
/// one: not a formula, not max(a, b, planes) with a and b curved, a plane not perpendicular to an axis,
/// creases off, another method, a region or cells given, an operand with creases of its own or not
/// crossing the planes' box. The mesh is outward and a 2-manifold, closed where the planes and the
/// operands' solids keep the part inside the box, else open exactly on the box's faces; every vertex
/// where two faces meet lies on both to 1e-9 of the box's diagonal. `stats` holds the lattice's run with
/// the crease and caps added (MeshStats::creases: faces, caps, crease vertices; stages "creases", "caps").
/// \throw CreaseError naming the place where the faces or caps cannot be joined; the errors of
///        mesh_surface().
std::optional<Mesh> mesh_capped_curved_cut(const Surface& surface, const Settings& settings,
                                           MeshStats* stats);

}  // namespace isopatch
