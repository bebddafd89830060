#pragma once
// The boundary of one face of max(s, o) where the box cuts the part open (curved_cut.hpp): the face
// F = {s = 0, o < 0} in the box is bounded by the crease's arcs (from the box to the box) and by the
// curves where s = 0 meets the box inside o's solid. A mesh of s made in the box has those curves as its
// own boundary, so each boundary loop of F is an arc, then the mesh's boundary vertices from where the arc
// ends to where the next arc starts, then that arc, and so on; a boundary loop of the mesh wholly inside
// o is one of F's loops by itself. The loops close F's trimmed mesh like the closed crease loops do
// (zipped_face.hpp). docs/lattices.md.

#include <isopatch/mesh.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace isopatch {

/// One point of a loop of F's boundary: a crease arc's point (`arc` >= 0: that arc, at `index`) or a
/// vertex of the mesh's boundary (`arc` -1, `index` the vertex).
struct BoundaryPoint {
  std::int64_t arc = -1;
  std::uint32_t index = 0;
};

/// The boundary loops of `triangles` (an edge-manifold triangle set): each in its triangles' direction
/// (the triangles on its left), starting at its smallest vertex, the loops in the order of those. A
/// boundary that passes a vertex twice is cut there into loops (each vertex is visited once).
std::vector<std::vector<std::uint32_t>> triangle_boundary_loops(const std::vector<Triangle>& triangles);

/// F's boundary loops, each with F on its left (the mesh's orientation), from `mesh` (a mesh of s = 0
/// whose boundary lies on the box's faces, triangles along grad s), `inside` (one flag per vertex: o < 0
/// there) and `arcs` (the crease's arcs as points in F's boundary direction: F on their left, each from
/// the box to the box). Each arc's first point is matched to the boundary edge of the mesh where o turns
/// from negative to positive, its last to one where it turns back, the nearest within `reach` of each.
/// \throw CreaseError naming the place when an arc end has no such edge near it, or an edge where o changes
///        sign has no arc end (a crease the tracing missed, or one closer to another than `reach`).
std::vector<std::vector<BoundaryPoint>> box_boundary_loops(const Mesh& mesh,
                                                           const std::vector<std::uint8_t>& inside,
                                                           const std::vector<std::vector<Vec3>>& arcs,
                                                           double reach);

/// The join where the trimmed face still reaches the box: its boundary loops that pass through vertices
/// of F's boundary loops (`loops`, ids into `positions`, F on their left) are cut there into runs, each
/// joined to the piece of F's loop between the same two vertices (band_join.hpp zip_between); a run that
/// is an edge of F's loop is F's boundary itself. What touches nothing is left to the crease walk.
struct BoxJoin {
  std::vector<Triangle> triangles;                        ///< the bands between runs and F's loops
  std::vector<std::vector<std::uint32_t>> free_loops;     ///< F's loops no trimmed boundary passes through
  std::vector<std::vector<std::uint32_t>> free_boundary;  ///< trimmed boundary loops through none of F's
};

/// As above, from the trimmed face's boundary loops (`boundary`, the face on their left). nullopt with
/// `failure` set when a run leads from one of F's loops to another, or an edge of F's loops is covered
/// twice or not at all.
std::optional<BoxJoin> join_at_the_box(const std::vector<Vec3>& positions,
                                       const std::vector<std::vector<std::uint32_t>>& loops,
                                       const std::vector<std::vector<std::uint32_t>>& boundary,
                                       std::string& failure);

}  // namespace isopatch
