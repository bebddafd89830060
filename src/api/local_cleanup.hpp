#pragma once
// The surface-bound clean-up (remesh.hpp) of a part of a mesh only: the triangles within a few rings of
// some vertices, cut out as their own mesh whose boundary is held bit for bit, cleaned up, and put back.
// A face joined to its crease by a band of new triangles (zipped_face.hpp) needs the clean-up at the band
// alone; the rest of it was cleaned up by the mesher that made it.

#include <isopatch/mesh.hpp>
#include <isopatch/remesh.hpp>
#include <isopatch/surface.hpp>

#include <cstdint>
#include <vector>

namespace isopatch {

/// The vertices of `triangles` (oriented, each edge in at most two) where two or more fans of them meet:
/// more than one boundary edge leaves the vertex (a bow tie), in increasing order.
std::vector<std::uint32_t> pinched_vertices(const std::vector<Triangle>& triangles);

/// Cleans up `mesh` (a 2-manifold mesh of `surface`, triangles along grad f) within `rings` rings of the
/// vertices with `seed` set, with `settings` (hold_cut is set: the part's boundary, and `mesh`'s own,
/// keep their positions bit for bit; the part is widened until its boundary has no vertex where two fans
/// meet). Vertices outside the part keep their ids; the part's new vertices are appended, and vertices
/// it no longer uses are left unreferenced. \throw as remesh_on_surface().
void clean_up_near(Mesh& mesh, const Surface& surface, const std::vector<std::uint8_t>& seed, int rings,
                   RemeshSettings settings);

}  // namespace isopatch
