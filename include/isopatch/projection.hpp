#pragma once
/// \file projection.hpp
/// The projection mesher of Á. Sipos and P. Salvi, "Creating good quality meshes from smooth implicit
/// surfaces", WAIT 2021 (section 2), for whole surfaces: an octree whose surface cells each hold one
/// disk-like sheet; per cell, the loop of edge crossings (corners) spans a barycentric base patch over a
/// regular n-gon, triangulated by a fixed template (concentric rings, valence 6 inside); every vertex is
/// moved onto f = 0 along the barycentric interpolation of the corners' cell-edge directions. Boundary
/// vertices are computed once per shared side and referenced by both patches, so the mesh is watertight
/// without welding. A patch whose rays meet the surface too obliquely, or that flips a triangle, is
/// rejected and the partition refined.
///
/// With Settings::base = Coons (the paper's second base surface, sec. 2.1; Salvi's multi-sided C0 Coons
/// patch, WAIT 2020), each side is first traced as a dense polyline on face-plane ∩ {f = 0} and
/// resampled by arc length, so boundary vertices sit on f = 0 before any projection; interior base points
/// come from the Coons patch over those curves and are projected along the interpolated unit gradients of
/// the corners.
///
/// The octree is adaptive: a cell whose patch is rejected, or whose topology is in doubt, is split
/// locally (2:1 balanced; a coarse patch takes its finer neighbours' crossings as extra flat corners, so
/// patches have up to 12 sides), at most Settings::refinement_levels below the starting depth. Cells
/// that still fail there are closed by a fan over their shared boundary (counted as fallback cells).

#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

namespace isopatch {

/// Meshes f = 0 inside settings.box (or surface.box()). Output: an indexed triangle mesh, normals along
/// grad f, vertices on f = 0 to about 1e-13 of a cell (fallback fan centres excepted, see stats).
/// \throw InputError for settings out of range; EvaluationError when f or grad f is NaN/inf where
///        needed; NoSurfaceError when no cell down to max_depth holds a sign change; LimitError on cancel
///        or when the output would exceed settings.max_vertices.
Mesh mesh_projection(const Surface& surface, const Settings& settings, MeshStats* stats = nullptr);

}  // namespace isopatch
