// Sample-based cell tests. They are heuristics (they look at samples, not at the whole cell); the
// reasons they imply a single disk when they hold everywhere are in docs/algorithms.md 2.9.5.
#include "partition/cell_tests.hpp"
#include "partition/convex_cell_tests.hpp"

#include "core/cyclic.hpp"
#include "partition/sample_cache.hpp"

#include <Eigen/Geometry>

namespace isopatch {

int sign_changes(double first, std::span<const double> interior, double last) {
  int changes = 0;
  bool previous = is_negative(first);
  for (double v : interior) {
    if (is_negative(v) != previous) ++changes;
    previous = is_negative(v);
  }
  if (is_negative(last) != previous) ++changes;
  return changes;
}

bool in_plane_gradients_agree(std::span<const Vec3> gradients, int axis) {
  // The general test with the axis as the normal: g - (g . e) e zeroes that component exactly.
  return in_plane_gradients_agree(gradients, Vec3::Unit(axis));
}

bool gradients_within_cone(std::span<const Vec3> gradients, double cos_max) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& g : gradients) {
    const double norm = g.norm();
    if (!(norm > 0.0) || !g.allFinite()) return false;  // zero or not finite: no cone
    mean += g / norm;
  }
  const double mean_norm = mean.norm();
  if (!(mean_norm > 0.0)) return false;
  mean /= mean_norm;
  for (const Vec3& g : gradients)
    if (g.dot(mean) < cos_max * g.norm()) return false;
  return true;
}

Vec3 newell_normal(std::span<const Vec3> points) {
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  Vec3 normal = Vec3::Zero();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec3 a = points[k] - centroid;
    const Vec3 b = points[next(k, points.size())] - centroid;
    normal += a.cross(b);
  }
  return normal;
}

}  // namespace isopatch
