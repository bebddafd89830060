#pragma once
// Proofs that triangles of a mesh meet only where they share vertices and edges, for the
// self-intersection check (self_intersection.cpp): 99% of the triangle pairs whose boxes overlap share a
// vertex (1.36M of 1.38M on a 114k-vertex torus), and the exact tests of those pairs were about half the
// check's time.
//
// Around one vertex (flat fans): the vertex v has a closed fan (its triangles form one cycle v a_i
// a_{i+1}, each edge v a_i in two of them with opposite directions), and dropping one coordinate axis,
// every triangle of the fan keeps the same orientation, exactly (orient2d of exact_predicates.hpp on the
// two other coordinates, none zero), and the fan winds once around v: the wedges v a_i a_{i+1}, each less
// than a half turn, cover the plane once (counted exactly by the wedges that hold the direction of the
// first kept axis, with coordinate comparisons only). Then the projected triangles have disjoint
// interiors, and meet only in the projected vertex v or the projection of their common edge; the
// projection is one-to-one on each triangle, so two triangles of the fan share no other point in space.
//
// What the proof of whole patches (flat_discs.hpp) reads besides: each triangle's orientation in the
// three projections and, for each edge, the triangle on its other side.

#include <isopatch/mesh.hpp>

#include "core/default_init_allocator.hpp"

#include <cstdint>
#include <vector>

namespace isopatch::analysis {

/// What the proofs read of a mesh, computed once.
struct MeshFans {
  /// neighbours[3 t + e] for an edge in one triangle only (the mesh's boundary).
  static constexpr std::uint32_t kOpen = 0xFFFFFFFFU;
  /// neighbours[3 t + e] for an edge in more than two triangles, or in two with the same direction.
  static constexpr std::uint32_t kTangled = 0xFFFFFFFEU;

  /// Per triangle: bit k when it turns counter-clockwise with axis k dropped (drop_axis of
  /// segments_2d.hpp), bit 3 + k when clockwise; 0 for a triangle that repeats an index.
  std::vector<std::uint8_t> triangle_turns;
  /// Per triangle t and edge e (from t[e] to t[e + 1]): the triangle holding the edge the other way,
  /// kOpen or kTangled. Triangles that repeat an index are no one's neighbour and have none.
  UninitialisedVector<std::uint32_t> neighbours;
  /// Per vertex: one of its triangles that repeat no index (kOpen for none), and how many it has (255
  /// for 255 or more).
  std::vector<std::uint32_t> first_triangles;
  std::vector<std::uint8_t> fan_sizes;
};

/// Everything above, in parallel (the neighbours across the edges into each vertex found among its
/// triangles); the same for any number of threads. \pre check_mesh passed; fewer than 2^32 - 2
/// triangles. Memory: 13 bytes per triangle and 5 per vertex, and while it runs the triangles at each
/// vertex (12 bytes per triangle and 4 per vertex).
MeshFans mesh_fans(const Mesh& mesh);

/// Whether the proof above covers the fan of vertex v, walked in order across the edges into v from its
/// first triangle (one cycle through all its triangles).
bool flat_fan(const Mesh& mesh, const MeshFans& fans, std::uint32_t v);

/// flat_fan for every vertex: 1 or 0. \pre check_mesh passed.
std::vector<std::uint8_t> flat_fans(const Mesh& mesh);

}  // namespace isopatch::analysis
