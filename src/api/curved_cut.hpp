#pragma once
// Two smooth solids intersected, f = max(a, b) (csg/capped_shape.hpp CutShape): a lattice cut by a
// sphere, a sheet inside a cylinder's solid, a ball with a bored bump. Each operand is meshed whole by
// the smooth mesher (the multiresolution refinement, any genus), the crease a = b = 0 is traced once on
// a's mesh (crease_loops.hpp), and each mesh is trimmed to the other's solid and joined to the crease
// (zipped_face.hpp): no face is ever cut into discs, so faces of hundreds of handles are meshed like any
// surface. Two smooth solids united, f = min(a, b) (a lattice with a solid insert), are -max(-a, -b):
// that intersection meshed and turned over (CutShape::united). docs/lattices.md.

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <optional>

#include "csg/capped_shape.hpp"

namespace isopatch {

/// The mesh of `surface` as two smooth solids intersected or united, or nullopt when it is not one: not a
/// formula, not max(a, b) or min(a, b) with both operands curved, creases off, another method, a region or
/// cells given, an operand with creases of its own, an operand that does not cross the box, or a union
/// of two solids that interval bounds show to stay off the box's faces (left to the general crease path). The
/// mesh is outward and a 2-manifold, closed when one operand's solid lies inside the box; otherwise the box
/// cuts the part open (a lattice inside a ball larger than the box): its boundary lies on the box's faces,
/// and the crease runs in arcs from the box to the box whose ends lie on both surfaces and exactly on the
/// face. Every crease vertex lies on a = 0 and b = 0 to 1e-9 of the box's diagonal, every other vertex on its
/// face. `stats` holds the lattice operand's run with the other's vertices and the crease added
/// (MeshStats::creases, stage "caps"). \throw CreaseError naming the place when the faces cannot be joined
/// (surfaces meeting tangentially,
///        a feature narrower than an edge at the crease); the errors of mesh_surface().
std::optional<Mesh> mesh_curved_cut(const Surface& surface, const Settings& settings, MeshStats* stats);

/// mesh_curved_cut() for the two operands of `shape` in `settings.box` (given): nullopt when an operand
/// has creases of its own or does not cross the box, or `shape` is united and both solids stay off the
/// box's faces. An operand's closed mesh is the cutter only when it encloses a positive volume (the
/// sphere of -b, around an unbounded solid, is not). Where the box cuts the part, the operands' cuts are
/// first split on the cut curve (CleanupSettings::split_cut); where their faces do not join, or join
/// with a triangle under 25 degrees, the operands are meshed again with the mesher's cuts and joined with
/// every fallback, and the mesh with the larger smallest angle is kept. \throw as mesh_curved_cut().
std::optional<Mesh> mesh_two_solids(const CutShape& shape, const Settings& settings, MeshStats* stats);

}  // namespace isopatch
