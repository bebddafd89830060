#pragma once
// Exact tests on points and segments of a coordinate plane, for the self-intersection check
// (self_intersection.cpp: triangles in one plane) and its proof of flat discs (flat_discs.cpp: the
// projected boundary of a patch). Every decision is a sign of exact_predicates.hpp or a comparison of
// coordinates, never a rounded difference.

#include <isopatch/geometry.hpp>

#include <algorithm>
#include <cmath>

#include "analysis/exact_predicates.hpp"

namespace isopatch::analysis {

/// A point of the plane that drops one coordinate axis.
struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

/// v without its coordinate `dropped` (0, 1, 2): the next two axes in cyclic order, so that a triangle
/// whose normal points along +dropped turns counter-clockwise.
inline Point2 drop_axis(const Vec3& v, int dropped) {
  const int i = (dropped + 1) % 3, j = (dropped + 2) % 3;
  return {v[i], v[j]};
}

inline int orient2d(Point2 a, Point2 b, Point2 c) {
  return exact::orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

/// Signs that are not strictly one positive and one negative.
inline bool opposite_or_zero(int s, int t) {
  return s * t <= 0;
}

/// Signs of which none is positive, or none negative.
inline bool one_side(int s1, int s2, int s3) {
  const bool negative = s1 < 0 || s2 < 0 || s3 < 0;
  const bool positive = s1 > 0 || s2 > 0 || s3 > 0;
  return !(negative && positive);
}

/// Closed segments pq and ab meet (touching and collinear overlap included).
inline bool segments_meet_2d(Point2 p, Point2 q, Point2 a, Point2 b) {
  const int d1 = orient2d(a, b, p), d2 = orient2d(a, b, q);
  if (d1 == 0 && d2 == 0) {  // collinear: overlap of the projections on the longer axis
    const bool use_x = std::abs(q.x - p.x) + std::abs(b.x - a.x) >= std::abs(q.y - p.y) + std::abs(b.y - a.y);
    const auto key = [use_x](Point2 v) { return use_x ? v.x : v.y; };
    return std::max(std::min(key(p), key(q)), std::min(key(a), key(b))) <=
           std::min(std::max(key(p), key(q)), std::max(key(a), key(b)));
  }
  return opposite_or_zero(d1, d2) && opposite_or_zero(orient2d(p, q, a), orient2d(p, q, b));
}

/// Closed triangle abc contains p.
inline bool contains_2d(Point2 a, Point2 b, Point2 c, Point2 p) {
  return one_side(orient2d(a, b, p), orient2d(b, c, p), orient2d(c, a, p));
}

}  // namespace isopatch::analysis
