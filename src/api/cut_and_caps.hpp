#pragma once
// One smooth solid cut by planes and closed by planar caps, the meshing step shared by capped solids
// and shells (capped_meshing.hpp): g = 0 meshed by the smooth mesher with the planes as its region,
// the caps (planar_caps.hpp), the last angle repair and the 2-manifold check. docs/lattices.md.

#include <isopatch/convex_region.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>

namespace isopatch {

/// A cut vertex lies on its planes within this share of the box diagonal (the smooth mesher puts it
/// there to rounding).
inline constexpr double kCapOnPlane = 1e-9;

/// What to mesh: g < 0 (`smooth`; null for a polyhedron alone) inside `planes`, of which the first
/// `capped` are the part's (capped) and the rest a region's (cutting it open); `closed` when the part's
/// polyhedron lies in `box` and no region cuts it.
struct CappedPart {
  SurfacePtr smooth;
  ConvexRegion planes;
  std::size_t capped = 0;
  bool closed = true;
  Box box;
  bool reversed = false;  ///< a shell's hollows: the mesh's orientation turned inside out
};

/// Whether the polyhedron of `planes` is bounded, has a face, and lies in `box` (to `margin`; a negative
/// margin asks for that much clearance).
bool polyhedron_inside(const ConvexRegion& planes, const Box& box, double margin);

/// Whether one of the first `capped` planes bounds a face of the polyhedron of `planes` inside `box`.
bool polyhedron_meets(const ConvexRegion& planes, std::size_t capped, const Box& box);

/// The settings `part.smooth` is meshed with for its cut: the planes as the region, creases off, and
/// where the part's polyhedron reaches a face of the box, the box grown by two edges (the edge length
/// kept at the given box's).
Settings cut_settings(const CappedPart& part, const Settings& settings);

/// \throw LimitError("max_vertices") when the caps could hold more vertices than settings.max_vertices.
void check_caps_fit(const CappedPart& part, const Settings& settings);

/// `mesh`, the cut (g = 0 meshed with cut_settings(), by one process or in blocks; empty for a
/// polyhedron alone), closed as mesh_cut_and_caps() closes it: the caps, the narrow corners' flips and
/// the last angle repair.
/// \throw as mesh_cut_and_caps() (CreaseError when the result is not the 2-manifold expected).
Mesh close_cut_with_caps(Mesh mesh, const CappedPart& part, const Settings& settings, MeshStats* stats,
                         double analysis);

/// The part's mesh: closed and outward when `closed`, else open exactly on the box's faces and the
/// region's planes; `stats` gets the smooth run's statistics, MeshStats::creases (`analysis`
/// counted in the stage "creases") and the stage "caps".
/// \throw CreaseError naming what is not a 2-manifold; LimitError("max_vertices") for caps beyond the
///        budget; the errors of mesh_surface().
Mesh mesh_cut_and_caps(const CappedPart& part, const Settings& settings, MeshStats* stats, double analysis);

}  // namespace isopatch
