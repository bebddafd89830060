// The faces of a convex polyhedron (facet_polygons.hpp).
#include "api/facet_polygons.hpp"

#include <array>
#include <cmath>
#include <cstddef>

namespace isopatch {

namespace {

/// Keeps the part of `polygon` where `value` <= 0; new sides along the cut get `label`; corners within
/// `merge` of the next are dropped.
void clip(FacetPolygon& polygon, const auto& value, int label, double merge) {
  const std::size_t n = polygon.corners.size();
  if (n == 0) return;
  FacetPolygon out;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& a = polygon.corners[k];
    const Vec3& b = polygon.corners[(k + 1) % n];
    const double va = value(a), vb = value(b);
    if (va <= 0.0) {
      out.corners.push_back(a);
      out.across.push_back(polygon.across[k]);
    }
    if ((va <= 0.0) != (vb <= 0.0)) {
      out.corners.push_back(a + (va / (va - vb)) * (b - a));
      out.across.push_back(va <= 0.0 ? label : polygon.across[k]);
    }
  }
  // A side entered and left at the same corner (a cut through a corner) leaves a repeated corner.
  FacetPolygon clean;
  for (std::size_t k = 0; k < out.corners.size(); ++k) {
    const Vec3& next = out.corners[(k + 1) % out.corners.size()];
    if ((out.corners[k] - next).norm() > merge) {
      clean.corners.push_back(out.corners[k]);
      clean.across.push_back(out.across[k]);
    }
  }
  polygon = clean.corners.size() >= 3 ? clean : FacetPolygon{};
}

double area(const FacetPolygon& polygon, const Vec3& normal) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t k = 0; k < polygon.corners.size(); ++k)
    sum += polygon.corners[k].cross(polygon.corners[(k + 1) % polygon.corners.size()]);
  return 0.5 * sum.dot(normal);
}

}  // namespace

double plane_value(const HalfSpace& h, const Vec3& p) {
  return h.a * p.x() + h.b * p.y() + h.c * p.z() + h.d;
}

std::vector<FacetPolygon> facet_polygons(const ConvexRegion& planes, const Box& box) {
  std::vector<FacetPolygon> out(planes.size());
  const double reach = 2.0 * box.diagonal();
  const double merge = 1e-12 * box.diagonal();
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const Vec3 n(planes[i].a, planes[i].b, planes[i].c);
    const Vec3 origin = box.centre() - plane_value(planes[i], box.centre()) * n;
    // u x v = n: counter-clockwise about n.
    const Vec3 u = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    const Vec3 v = n.cross(u);
    FacetPolygon& polygon = out[i];
    for (const auto& [su, sv] : std::array<std::array<double, 2>, 4>{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}}) {
      polygon.corners.push_back(origin + reach * (su * u + sv * v));
      polygon.across.push_back(-1);
    }
    for (std::size_t j = 0; j < planes.size() && !polygon.corners.empty(); ++j)
      if (j != i)
        clip(
            polygon, [&](const Vec3& p) { return plane_value(planes[j], p); }, static_cast<int>(j), merge);
    for (int axis = 0; axis < 3 && !polygon.corners.empty(); ++axis) {
      clip(
          polygon, [&](const Vec3& p) { return p[axis] - box.hi[axis]; }, -1, merge);
      clip(
          polygon, [&](const Vec3& p) { return box.lo[axis] - p[axis]; }, -1, merge);
    }
    if (!polygon.corners.empty() && !(area(polygon, n) > 1e-12 * box.diagonal() * box.diagonal()))
      polygon = FacetPolygon{};
  }
  return out;
}

}  // namespace isopatch
