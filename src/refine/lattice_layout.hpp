#pragma once
// Where the refinement puts its vertices and triangles: every base triangle cut into k^2 triangles
// along a regular lattice of its barycentric domain. Vertex numbers: the base vertices first (kept),
// then the k - 1 points of every base edge, from its lower to its higher end, then the (k-1)(k-2)/2
// inner points of every base triangle. A point on a base edge is numbered by that edge alone, so the
// two triangles beside it use the same vertex (watertight, and the same whichever comes first).

#include <isopatch/mesh.hpp>

#include <array>
#include <cstdint>

#include "refine/base_edges.hpp"

namespace isopatch::refine {

/// The most a base edge may be cut into (the refinement level k).
inline constexpr int kMaxLevel = 32;

class LatticeLayout {
 public:
  /// \pre 1 <= level <= kMaxLevel; `edges` is base_edges(base) and outlives the layout.
  /// \throw LimitError when the refined mesh would need more than 2^32 - 1 vertex numbers.
  LatticeLayout(const Mesh& base, const BaseEdges& edges, int level);

  int level() const { return k_; }
  std::size_t base_vertices() const { return base_vertices_; }
  std::size_t vertex_count() const { return vertex_count_; }
  std::size_t triangle_count() const { return triangles_ * static_cast<std::size_t>(k_ * k_); }
  /// Points inside one base triangle: (k-1)(k-2)/2.
  std::size_t inner_per_triangle() const { return inner_; }

  /// Point j (1..k-1) of edge e, at j/k of the way from its lower to its higher end.
  std::uint32_t edge_point(std::uint32_t e, int j) const {
    return static_cast<std::uint32_t>(edge_start_ + static_cast<std::size_t>(e) * (k_ - 1) + (j - 1));
  }
  /// The first vertex number of triangle t's inner points (row by row, see vertex()).
  std::size_t inner_start(std::size_t t) const { return inner_start_ + t * inner_; }
  /// The vertex at lattice point (i, j) of triangle t: barycentric weights ((k-i-j)/k, i/k, j/k) of
  /// its corners 0, 1, 2. \pre i, j >= 0, i + j <= k.
  std::uint32_t vertex(std::size_t t, int i, int j) const;
  /// Index of the inner point (i, j) (i, j >= 1, i + j <= k - 1) among triangle t's inner points.
  std::size_t inner_index(int i, int j) const {
    // Rows j = 1..k-2 hold k - 1 - j points each, i = 1..k-1-j.
    const std::size_t before =
        static_cast<std::size_t>(j - 1) * (k_ - 1) - static_cast<std::size_t>((j - 1) * j) / 2;
    return before + static_cast<std::size_t>(i - 1);
  }
  /// Appends the k^2 triangles of base triangle t to `out`, oriented as the base triangle, in a fixed
  /// order (row by row: up then down triangles).
  void emit_triangles(std::size_t t, Triangle* out) const;

 private:
  const Mesh& base_;
  const BaseEdges& edges_;
  int k_;
  std::size_t base_vertices_ = 0;
  std::size_t triangles_ = 0;
  std::size_t edge_start_ = 0;
  std::size_t inner_start_ = 0;
  std::size_t inner_ = 0;
  std::size_t vertex_count_ = 0;
};

}  // namespace isopatch::refine
