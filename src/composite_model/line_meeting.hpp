#pragma once
/// \file line_meeting.hpp
/// Where two lines p + alpha u and q + beta v come closest: the least-squares solution of
/// alpha u - beta v = w with w = q - p, used to place the middle control point of a boundary conic where
/// the tangent lines at its two ends meet (Sipos, Varady, Salvi & Vaitkus 2020, boundary curves of
/// I-patches from a control polyhedron; Varady & Rockwood 1997, setback vertex blends).

#include <isopatch/geometry.hpp>

#include <cmath>

namespace isopatch {

/// Solves alpha u - beta v = w in the least-squares sense. False (alpha, beta untouched) when u and v
/// are parallel to within 1e-12 of their lengths.
inline bool meet(const Vec3& u, const Vec3& v, const Vec3& w, double& alpha, double& beta) {
  const double a11 = u.dot(u), a12 = -u.dot(v), a22 = v.dot(v);
  const double r1 = u.dot(w), r2 = -v.dot(w);
  const double det = a11 * a22 - a12 * a12;
  if (!(std::abs(det) > 1e-12 * a11 * a22)) return false;
  alpha = (r1 * a22 - r2 * a12) / det;
  beta = (a11 * r2 - a12 * r1) / det;
  return true;
}

}  // namespace isopatch
