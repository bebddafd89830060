#pragma once
// A CSG shape cut open by planes and meshed along its creases: by a region (Settings::region), and by
// the box where the shape's creases or faces leave it. The shape intersected with the cutting planes,
// max(f, p_1, ..., p_k), is a closed solid whose creases include those where f meets the planes; it is
// meshed along its creases (crease_meshing.hpp) in a box grown so that nothing touches it, then the
// triangles lying on the cutting planes are taken away. What is left is f = 0 inside the planes, open
// along exact curves on them, with f's own creases exact up to the cut (docs/creases.md, "Cut open").

#include <isopatch/convex_region.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>

#include "api/crease_meshing.hpp"

namespace isopatch {

/// The planes that cut `surface` open for `settings`: the region's, and with `by_box` the six planes
/// of the meshing box (settings.box, else the region's or the surface's box), unit normals out of the
/// part (a x + b y + c z + d <= 0 inside).
ConvexRegion cutting_planes(const Surface& surface, const Settings& settings, bool by_box);

/// The most cutting planes (a region of more is meshed through the partition, as a smooth surface).
inline constexpr std::size_t kMostCuttingPlanes = 64;

/// Meshes `surface` (a formula with creases) cut open by `planes` along its creases, as above, with the
/// edge length of the meshing box (the default when none is given); a frame in `settings` is not used
/// (the crease path has no partition to turn: its pieces are meshed on their own, in the user's
/// coordinates). Vertices on a cutting plane are put on it exactly (an axis-aligned plane: the coordinate
/// itself). Returns no mesh when the cut shape is not meshed along creases (more than kMostCuttingPlanes
/// planes, no crease, or a crease that leaves the box: said in the result), and then the caller meshes
/// as before. `stats` gets the crease run's statistics, with creases.cut_planes set.
/// \throw CreaseError when the cut shape cannot be meshed along its creases; NoSurfaceError when nothing
///        of the shape is left inside the planes; the errors of mesh_along_creases().
CreasedMesh mesh_clipped_along_creases(const Surface& surface, const ConvexRegion& planes,
                                       const Settings& settings, MeshStats* stats);

}  // namespace isopatch
