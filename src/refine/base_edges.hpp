#pragma once
// The edges of a base mesh, numbered once: the key by which the refinement places the points of an
// edge, so that the two triangles beside it share them (watertight by construction, no welding).

#include <isopatch/mesh.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace isopatch::refine {

struct BaseEdges {
  /// Per edge: its two vertices, lower index first; edges sorted by (first, second).
  std::vector<std::array<std::uint32_t, 2>> ends;
  /// Per edge: how many triangles use it (1: a boundary edge).
  std::vector<std::uint8_t> uses;
  /// Per triangle: the edge of side s, from corner s to corner (s + 1) % 3.
  std::vector<std::array<std::uint32_t, 3>> of_triangle;

  std::size_t size() const { return ends.size(); }
  bool boundary(std::uint32_t e) const { return uses[e] == 1; }
};

/// The edges of `base`, numbered in ascending (lower end, higher end) order, so the numbering depends on
/// the mesh alone. Takes O(T log T) time for T triangles.
/// \pre every index of base.triangles is below base.vertex_count().
/// \throw InputError when an edge is used by more than 255 triangles (no mesh of a surface does that).
BaseEdges base_edges(const Mesh& base);

}  // namespace isopatch::refine
