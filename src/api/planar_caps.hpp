#pragma once
// The planar caps that close a smooth surface cut open by a convex polyhedron: on each face of the
// polyhedron, the region where the solid g < 0 meets it, bounded by the cut's own boundary edges
// (exactly on the plane and on g = 0) and by the polyhedron's edges, sampled once and shared by the
// two caps beside them. Each cap is triangulated in its plane from the equilateral lattice (planar/),
// then cleaned up on the plane with its boundary held (remesh.hpp). docs/lattices.md.

#include <isopatch/convex_region.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>

namespace isopatch {

/// What close_with_caps() added.
struct CapReport {
  std::size_t caps = 0;             ///< planes with a cap
  std::size_t crease_vertices = 0;  ///< vertices on g = 0 and a plane, or on two planes
  std::size_t cap_vertices = 0;     ///< vertices added (polyhedron edges and cap interiors)
  std::size_t open_edges = 0;       ///< boundary edges of the cut left open on the box's faces
  std::size_t open_cap_edges = 0;   ///< boundary edges of the caps on the box's faces
};

/// Closes `mesh`, a mesh of g = 0 (`smooth`, triangles along grad g; null for a polyhedron: `mesh`
/// empty and every face a whole cap) cut open by `planes` (unit normals out of the solid; the first
/// `capped` are the part's and get caps, the rest a region's, which cut the part open like the box; every
/// boundary vertex on a plane to `tolerance`, those where the cut turns from one plane to the next on both),
/// with one cap per plane that the solid g <= 0 meets, oriented along the plane's normal, at edge length
/// `edge`. `settings` give the clean-up's preset; `box` clips the planes' polygons: where the polyhedron
/// leaves it, the box cuts the part open (the cut's boundary edges on the box's faces or a region's planes
/// and the caps' sides there stay boundary, exactly on them). `narrow_corners`: the cut's narrow corners
/// at the planes opened first (cap_wedges.hpp; off for a cut of two faces, whose flips would cross their
/// crease). \throw CreaseError naming the place when a
/// boundary edge lies on no plane or box face, or a cap's
///        boundary does not bound a region (curves crossing, not closing).
CapReport close_with_caps(Mesh& mesh, const Surface* smooth, const ConvexRegion& planes, std::size_t capped,
                          const Box& box, double edge, double tolerance, const Settings& settings,
                          bool narrow_corners = true);

}  // namespace isopatch
