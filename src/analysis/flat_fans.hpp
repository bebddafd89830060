#pragma once
// A proof that the triangles around a vertex meet only where they share vertices and edges, for the
// self-intersection check (self_intersection.cpp): 99% of the triangle pairs whose boxes overlap share a
// vertex (1.36M of 1.38M on a 114k-vertex torus), and the exact tests of those pairs were about half the
// check's time.
//
// The proof: the vertex v has a closed fan (its triangles form one cycle v a_i a_{i+1}, each edge v a_i
// in two of them with opposite directions), and dropping one coordinate axis, every triangle of the fan
// keeps the same orientation, exactly (orient2d of exact_predicates.hpp on the two other coordinates,
// none zero), and the fan winds once around v: the wedges v a_i a_{i+1}, each less than a half turn,
// cover the plane once (counted exactly by the wedges that hold the direction of the first kept axis,
// with coordinate comparisons only). Then the projected triangles have disjoint interiors, and meet
// only in the projected vertex v or the projection of their common edge; the projection is one-to-one
// on each triangle, so two triangles of the fan share no other point in space.

#include <isopatch/mesh.hpp>

#include <cstdint>
#include <vector>

namespace isopatch::analysis {

/// 1 for every vertex of `mesh` whose fan the proof above covers, 0 for the others (a boundary or
/// non-manifold vertex, a fan folded or turned over in every axis' projection, a repeated position).
/// Computed in parallel; the same for any number of threads. \pre check_mesh passed.
std::vector<std::uint8_t> flat_fans(const Mesh& mesh);

}  // namespace isopatch::analysis
