#pragma once
// A smooth solid capped by a convex polyhedron, f = max(g, p_1, ..., p_k) (csg/capped_shape.hpp),
// meshed as g = 0 cut open by the polyhedron's planes (the smooth mesher with the planes as its
// region: exact boundaries on them, the multiresolution refinement inside) and closed by planar caps
// (planar_caps.hpp): the lattice parts people print (a gyroid capped by its box), whose faces of high
// genus the general crease path cannot cut into discs. docs/lattices.md.

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <optional>
#include <vector>

#include "api/cut_and_caps.hpp"

namespace isopatch {

/// The mesh of `surface` as a capped smooth solid, or nullopt when it is not one: not a formula, not of
/// the form max(g, planes) (capped_shape.hpp), creases off, another method, given cells, no face of
/// the part in the box and region, g with creases of its own inside the box, or a polyhedron alone
/// in the box and outside a frame and a region (the general crease path meshes those). A frame
/// rotates the cut's partition; a polyhedron alone is its caps; the box and a region cut the part open
/// (its boundary exactly on their faces). The mesh is closed, outward, with every vertex of the cut on g = 0
/// and its plane (on both planes at the polyhedron's edges) and the caps' vertices on their planes; `stats`
/// holds the smooth run's statistics with the caps added (MeshStats::creases).
/// \throw CreaseError naming the place when the caps cannot close the cut (a plane tangent to g = 0 on
///        a cut edge, curves crossing); the errors of mesh_surface().
/// A lattice shelled by its box (csg/capped_shape.hpp ShelledShape) is meshed here too: the outer
/// polyhedron's caps and the hollows inside the inner one, closed and outward.
std::optional<Mesh> mesh_capped_shape(const Surface& surface, const Settings& settings, MeshStats* stats);

/// The mesh of a union whose complement is a capped shape (csg/capped_shape.hpp union_complement():
/// min(g, -P), the outside of the polyhedron P united with the lattice g < 0; or with two curved solids,
/// min(a, b, -P) as mesh_capped_curved_cut() takes max(-a, -b, P)): the complement's mesh by
/// mesh_capped_curved_cut() or mesh_capped_shape(), its triangles turned over. Nullopt when f is no
/// such union or those return nullopt.
/// 	hrow as those.
std::optional<Mesh> mesh_capped_complement(const Surface& surface, const Settings& settings,
                                           MeshStats* stats);

/// The parts mesh_capped_shape() meshes `surface` as (one for a capped solid; for a shell, the outer
/// polyhedron's caps, then the hollows, `reversed`), or nullopt under the same conditions. Each is
/// meshed by mesh_cut_and_caps(), or in blocks: its cut with cut_settings(), closed by
/// close_cut_with_caps(). Makes the crease analysis of g (nothing is meshed).
/// \throw the errors of that analysis (CreaseError, EvaluationError).
std::optional<std::vector<CappedPart>> split_capped_parts(const Surface& surface, const Settings& settings);

/// `part` appended to `mesh` (its numbers shifted), turned inside out when `reversed`.
Mesh append_capped_part(Mesh mesh, const Mesh& part, bool reversed);

}  // namespace isopatch
