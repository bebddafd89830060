#pragma once
/// \file self_intersection.hpp
/// Self-intersection test of a triangle mesh: pairs of triangles that meet other than in the vertices
/// and the edge they share (by index). A mesh that passes can be handed to solid modellers, boolean
/// operations and volume meshers; one that fails has folds or sheets passing through each other.
/// Candidate pairs come from a hierarchy of triangle bounding boxes traversed against itself (each pair
/// of overlapping boxes once), O(n log n) for meshes of even triangle size; subtrees proved one-to-one
/// under a coordinate projection (their triangles all turn one way and their boundary's image is a
/// plane graph that winds at most once around any point) are not entered, and pairs around a vertex
/// whose fan is so proved are skipped. Every decision uses exact orientation signs (a floating-point
/// filter, then exact expansions; Shewchuk 1997), so nearly coplanar neighbours and touching triangles
/// are classified as exactly as the positions allow.

#include <isopatch/mesh.hpp>

#include <array>
#include <cstddef>

namespace isopatch {

struct SelfIntersectionReport {
  std::size_t pairs = 0;  ///< intersecting pairs found (at most the limit asked for)
  bool capped = false;    ///< the search stopped at the limit: there may be more
  /// One intersecting pair (triangle indices, smaller first) and a point where they meet (a vertex
  /// of the pair's intersection, or a shared vertex for folded neighbours); meaningful when pairs > 0.
  std::array<std::size_t, 2> example{};
  Vec3 example_point = Vec3::Zero();
};

/// Finds the pairs of triangles of `mesh` that intersect: triangles without a common vertex that touch
/// or cross; triangles with one common vertex that meet anywhere else; triangles with a common edge
/// that lie in one plane on the same side of it (folded flat); triangles with the same three vertices.
/// Degenerate triangles (a repeated index) are skipped. Stops after `limit` pairs (then capped).
/// \throw InputError if a triangle refers to a vertex out of range or a position is not finite.
SelfIntersectionReport find_self_intersections(const Mesh& mesh, std::size_t limit = 1000);

}  // namespace isopatch
