#pragma once
// The planes a mesh may be cut open by: the faces of its box and the planes of its region. A refined
// base edge that lies on one of them stays on it: its points are put on the curve where that plane
// meets f = 0 (two equations), not merely on f = 0.

#include <isopatch/convex_region.hpp>
#include <isopatch/geometry.hpp>

#include <optional>
#include <vector>

namespace isopatch::refine {

/// n . x + offset = 0 on the plane, n a unit vector. A box face also keeps its axis, so that points on
/// it are put there exactly (p[axis] = the face's coordinate), as the meshers clamp the cut.
struct CutPlane {
  Vec3 normal = Vec3::UnitX();
  double offset = 0.0;
  int axis = -1;  ///< 0, 1, 2 for a box face; -1 for a region plane
};

class BoundaryPlanes {
 public:
  /// The six faces of `box` (when given) and the planes of `region` (unit normals).
  /// \param tolerance  how far from a region plane a point may lie and count as on it (> 0)
  BoundaryPlanes(const std::optional<Box>& box, const ConvexRegion& region, double tolerance);

  std::size_t size() const { return planes_.size(); }
  const CutPlane& operator[](std::size_t i) const { return planes_[i]; }
  /// Whether p lies on plane i: exactly for a box face, within the tolerance for a region plane.
  bool on(std::size_t i, const Vec3& p) const;
  /// The first plane that both a and b lie on, or -1.
  int common(const Vec3& a, const Vec3& b) const;
  /// p moved onto plane i (exactly onto a box face).
  Vec3 onto(std::size_t i, const Vec3& p) const;

 private:
  std::vector<CutPlane> planes_;
  double tolerance_;
};

}  // namespace isopatch::refine
