#pragma once
// A proof that a patch of triangles meets itself only where its triangles share vertices and edges, for
// the self-intersection check (self_intersection.cpp), which then skips every pair inside the patch: the
// subtrees of its tree (triangle_tree.hpp) over a smooth mesh are such patches, and on meshes of a
// million triangles their pairs were most of the check's time.
//
// The proof, for a set S of triangles and a coordinate axis k dropped (the projection P):
//  (a) every triangle of S turns the same way under P, exactly (orient2d, none zero);
//  (b) every edge of S lies in at most two triangles of the mesh, with opposite directions when two, so
//      that the boundary of S as a chain (the sum of its triangles' directed edges) is its edges whose
//      other triangle is not in S or that have none, and every vertex has as many of them in as out;
//  (c) under P, boundary edges meet only at a vertex they share by index, and edges that share one do
//      not overlap beyond it (exact segment tests of segments_2d.hpp);
//  (d) around each vertex with more than one boundary edge out (where S touches itself), the boundary
//      edges alternate out and in, in the angular order of their directions under P.
// Then P is one-to-one on S. The boundary's image is a plane graph (c) that cuts the plane into faces.
// For a point q on no projected edge, the triangles of S over q counted with their signs under P make
// the winding number d(q) of the boundary's image around q (the boundary of a sum of triangles is the
// sum of their boundaries); with all signs alike (a), d(q) is the number of triangles over q, so d >= 0,
// d = 0 far away, and d is constant on each face and one larger left of each edge than right of it. By
// (d), the sector between two edges that follow one another around a vertex lies left of both or right
// of both, so each face lies left of all its edges or right of all of them: faces of two kinds, every
// edge with a face of the first kind on its left and one of the second on its right, d one larger on
// the first. The second kind can only take d = 0 (else the first would have d = 0 and the second -1),
// so d is 0 or 1: projected triangles have disjoint interiors. Two points x != y of S over one point
// would each have triangles over an open sector next to it, the same sector (a second covering) unless
// both lie on the boundary (a point inside S has a whole disc of triangles over its neighbourhood: its
// fan covers it at least once), and two boundary points over one point contradict (c). So two
// triangles of S share no point in space other than what they share by index. Nothing assumes S
// connected, a disc, or its fans flat.

#include <isopatch/mesh.hpp>

#include <cstdint>
#include <vector>

#include "analysis/flat_fans.hpp"

namespace isopatch::analysis {

/// The mesh's triangles in the tree's order, as flat_disc reads them.
struct OrderedTriangles {
  const Mesh* mesh = nullptr;
  const MeshFans* fans = nullptr;
  const std::vector<std::uint32_t>* order = nullptr;  // the triangle at each position
  const std::uint32_t* position = nullptr;            // the position of each triangle (or past the end)
};

/// Whether the proof above holds for the triangles at positions [begin, end) of `triangles`, with an
/// axis k and a direction whose bit (MeshFans::triangle_turns) every one of them has in `turns`. When it
/// does and `boundary` is given, appends the vertices on the patch's boundary (the only ones where a
/// pair of triangles, one outside it, can still meet). Time linear in the triangles and n log n in the
/// boundary's edges; memory for the boundary alone.
bool flat_disc(const OrderedTriangles& triangles, std::uint32_t begin, std::uint32_t end, std::uint8_t turns,
               std::vector<std::uint32_t>* boundary = nullptr);

}  // namespace isopatch::analysis
