#pragma once
// The smallest interior angle of a triangle: one definition for the clean-up's checks, the refinement,
// the raw-defect statistics and the composite analysis.

#include <isopatch/geometry.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace isopatch {

/// The two edge vectors leaving the corner opposite the shortest edge of triangle (p0, p1, p2): the
/// corner of the smallest angle.
inline std::pair<Vec3, Vec3> smallest_angle_edges(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  const Vec3 p[3] = {p0, p1, p2};
  int opposite_shortest = 0;  // vertex i is opposite edge (i+1, i+2)
  double shortest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double l = (p[(i + 2) % 3] - p[(i + 1) % 3]).squaredNorm();
    if (l < shortest) shortest = l, opposite_shortest = i;
  }
  return {p[(opposite_shortest + 1) % 3] - p[opposite_shortest],
          p[(opposite_shortest + 2) % 3] - p[opposite_shortest]};
}

/// The smallest angle of triangle (p0, p1, p2) in degrees; 0 for a degenerate triangle.
inline double smallest_angle(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  const auto [u, v] = smallest_angle_edges(p0, p1, p2);
  return std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / std::numbers::pi;
}

/// Cosine of the smallest angle of triangle (p0, p1, p2), without trigonometry (for comparisons:
/// a larger cosine is a smaller angle). 1 for a degenerate triangle.
inline double smallest_angle_cosine(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  const auto [u, v] = smallest_angle_edges(p0, p1, p2);
  const double lengths = std::sqrt(u.squaredNorm() * v.squaredNorm());
  return lengths > 0.0 ? u.dot(v) / lengths : 1.0;
}

}  // namespace isopatch
