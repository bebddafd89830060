#pragma once
/// \file polyline_curve.hpp
/// A space curve given as a dense polyline, parameterized by normalized cumulative chord length, as
/// the boundary curves of the multi-sided C0 Coons patch are in Sipos & Salvi 2021 (footnote on
/// "curves as dense polylines") and in docs/algorithms.md 3.5.3. Unlike the authors' polyline class
/// (docs/algorithms.md 3.5.2), both end derivatives are taken from the knots, so neither is a zero vector.

#include <isopatch/geometry.hpp>

#include <span>
#include <vector>

namespace isopatch {

class PolylineCurve {
 public:
  /// \param points  p_0 .. p_N, N >= 1, consecutive points distinct (the total length is positive).
  /// \throw InputError when fewer than 2 points are given or the polyline has zero length.
  explicit PolylineCurve(std::vector<Vec3> points);

  /// The point at parameter u in [0, 1] (clamped): linear between the knots kappa_j = L_j / L, where
  /// L_j is the length up to p_j. Exactly p_0 at u = 0 and exactly p_N at u = 1, so evaluating at
  /// u = i / r resamples the polyline at equal arc length.
  Vec3 point(double u) const;
  /// (p_1 - p_0) / (kappa_1 - kappa_0): the derivative with respect to u at u = 0.
  Vec3 start_derivative() const;
  /// (p_N - p_{N-1}) / (kappa_N - kappa_{N-1}): the derivative with respect to u at u = 1.
  Vec3 end_derivative() const;

  const Vec3& front() const { return points_.front(); }
  const Vec3& back() const { return points_.back(); }
  double length() const { return length_; }
  std::span<const Vec3> points() const { return points_; }
  std::span<const double> knots() const { return knots_; }

 private:
  std::vector<Vec3> points_;
  std::vector<double> knots_;  // kappa_0 = 0 < ... < kappa_N = 1 (non-decreasing with repeated points)
  double length_ = 0.0;
};

}  // namespace isopatch
