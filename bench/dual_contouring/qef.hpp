#pragma once
/// \file qef.hpp
/// The quadratic error function of Dual Contouring (Ju, Losasso, Schaefer & Warren, "Dual contouring
/// of Hermite data", SIGGRAPH 2002, section 2.3): for the Hermite samples (p_i, n_i) of a cell, where
/// the surface crosses the cell's edges and its unit normal there, E(x) = sum_i (n_i . (x - p_i))^2.
/// It is kept as its normal equations (A^T A, A^T b) and minimised with a truncated pseudo-inverse
/// relative to the mass point of the samples, as the paper recommends. Benchmark code only.

#include <isopatch/geometry.hpp>

#include <cstddef>

namespace isopatch::bench {

class Qef {
 public:
  /// Adds the sample at `point` with unit normal `normal` (the zero vector when the gradient there is
  /// unusable: the point still counts for the mass point, its plane adds nothing). Points are best
  /// given relative to a nearby origin (the cell's corner) to keep the sums well conditioned.
  void add(const Vec3& point, const Vec3& normal);

  std::size_t count() const { return count_; }
  /// The mean of the sample points (the zero vector when there is none).
  Vec3 mass_point() const;
  /// The minimiser of E closest to the mass point: A^T A is decomposed by SVD, singular values below
  /// `truncation` times the largest are taken as zero (the directions along a flat or a crease stay at
  /// the mass point). Not clamped to anything.
  Vec3 minimiser(double truncation) const;

 private:
  Mat3 ata_ = Mat3::Zero();        // sum n_i n_i^T
  Vec3 atb_ = Vec3::Zero();        // sum n_i (n_i . p_i)
  Vec3 point_sum_ = Vec3::Zero();  // sum p_i
  std::size_t count_ = 0;
};

}  // namespace isopatch::bench
