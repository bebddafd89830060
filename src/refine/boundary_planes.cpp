// Box faces and region planes of a cut-open mesh (boundary_planes.hpp).
#include "refine/boundary_planes.hpp"

#include <cmath>

namespace isopatch::refine {

BoundaryPlanes::BoundaryPlanes(const std::optional<Box>& box, const ConvexRegion& region, double tolerance)
    : tolerance_(tolerance) {
  if (box)
    for (int a = 0; a < 3; ++a) {
      CutPlane lo, hi;
      lo.normal = -Vec3::Unit(a);
      lo.offset = box->lo[a];
      lo.axis = a;
      hi.normal = Vec3::Unit(a);
      hi.offset = -box->hi[a];
      hi.axis = a;
      planes_.push_back(lo);
      planes_.push_back(hi);
    }
  for (const HalfSpace& h : region) {
    const Vec3 n(h.a, h.b, h.c);
    const double length = n.norm();
    if (!(length > 0.0)) continue;  // validate_region refuses such a plane before meshing
    planes_.push_back({n / length, h.d / length, -1});
  }
}

bool BoundaryPlanes::on(std::size_t i, const Vec3& p) const {
  const CutPlane& c = planes_[i];
  if (c.axis >= 0) return p[c.axis] == -c.offset * c.normal[c.axis];
  return std::abs(c.normal.dot(p) + c.offset) <= tolerance_;
}

int BoundaryPlanes::common(const Vec3& a, const Vec3& b) const {
  for (std::size_t i = 0; i < planes_.size(); ++i)
    if (on(i, a) && on(i, b)) return static_cast<int>(i);
  return -1;
}

Vec3 BoundaryPlanes::onto(std::size_t i, const Vec3& p) const {
  const CutPlane& c = planes_[i];
  Vec3 q = p;
  if (c.axis >= 0) {
    q[c.axis] = -c.offset * c.normal[c.axis];
    return q;
  }
  return q - (c.normal.dot(q) + c.offset) * c.normal;
}

}  // namespace isopatch::refine
