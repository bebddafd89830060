#pragma once
/// \file domain.hpp
/// The regular n-gon parameter domain of an n-sided patch (n = 3..16), as in the multi-sided patches
/// of Salvi (C0 Coons, WAIT 2020) and the transfinite-surface library of Salvi & Várady.
///
/// THE ONE INDEXING CONVENTION OF src/ngon (every other file follows it; convert at a single place
/// if a formula from a paper indexes differently):
///   - corner k of a patch sits at domain vertex V_k, k = 0..n-1, counter-clockwise;
///   - side k runs from V_k to V_{k+1} (indices mod n);
///   - the point of side k at parameter t in [0, 1] is (1 - t) V_k + t V_{k+1} (side_point()).

#include <Eigen/Core>

#include <array>
#include <span>

namespace isopatch {

using Vec2 = Eigen::Vector2d;  ///< a point of a 2D parameter domain

/// The z component of the cross product of two plane vectors (twice the signed area of the triangle
/// they span; positive when b is counter-clockwise from a).
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// The regular n-gon: V_k = (cos(2 pi k/n), sin(2 pi k/n)) on the unit circle, except for n = 4, which
/// is the axis-aligned square V_0 = (1,1), V_1 = (-1,1), V_2 = (-1,-1), V_3 = (1,-1) (on it, Wachspress
/// coordinates are exactly bilinear). Vertices are counter-clockwise around the origin.
class Domain {
 public:
  static constexpr int kMinSides = 3;
  static constexpr int kMaxSides = 16;

  /// \throw InputError unless 3 <= n <= 12.
  explicit Domain(int n);

  int sides() const { return n_; }
  /// V_k for any integer k (taken mod n, negative k allowed).
  const Vec2& vertex(int k) const { return vertices_[static_cast<std::size_t>(wrap(k))]; }
  /// V_0 .. V_{n-1}.
  std::span<const Vec2> vertices() const { return {vertices_.data(), static_cast<std::size_t>(n_)}; }
  /// (1 - t) V_k + t V_{k+1}: the point of side k (taken mod n) at parameter t. Exactly V_k at t = 0
  /// and exactly V_{k+1} at t = 1. Every module computes boundary domain points with this function so
  /// that patches sharing a side agree bit for bit.
  Vec2 side_point(int k, double t) const;
  /// side_point(k, i / r) with t computed as double(i) / double(r): boundary vertex i of r on side k.
  /// \pre r >= 1.
  Vec2 side_point(int k, int i, int r) const {
    return side_point(k, static_cast<double>(i) / static_cast<double>(r));
  }
  /// k mod n in 0..n-1.
  int wrap(int k) const { return ((k % n_) + n_) % n_; }

 private:
  int n_;
  std::array<Vec2, kMaxSides> vertices_;
};

}  // namespace isopatch
