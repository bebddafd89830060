// A surface in a rotated frame (rotated_surface.hpp).
#include "surface/rotated_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace isopatch {
namespace {

Box bounds_of_corners(const Box& b, const Mat3& m) {
  Box out{Vec3::Constant(std::numeric_limits<double>::infinity()),
          Vec3::Constant(-std::numeric_limits<double>::infinity())};
  for (int i = 0; i < 8; ++i) {
    const Vec3 c((i & 1) ? b.hi.x() : b.lo.x(), (i & 2) ? b.hi.y() : b.lo.y(), (i & 4) ? b.hi.z() : b.lo.z());
    const Vec3 p = m * c;
    out.lo = out.lo.cwiseMin(p);
    out.hi = out.hi.cwiseMax(p);
  }
  // Outward by a few rounding errors of the product, so the result holds every rotated point.
  const Vec3 pad = Vec3::Constant(8.0 * std::numeric_limits<double>::epsilon() *
                                  std::max(out.lo.cwiseAbs().maxCoeff(), out.hi.cwiseAbs().maxCoeff()));
  return Box{out.lo - pad, out.hi + pad};
}

}  // namespace

Box frame_bounds(const Box& box, const Mat3& r) {
  return bounds_of_corners(box, r.transpose());
}

RotatedSurface::RotatedSurface(const Surface& surface, const Mat3& rotation, const Box& box)
    : Surface(surface.name(), box), surface_(surface), r_(rotation) {}

Box RotatedSurface::user_box(const Box& frame_box) const {
  return bounds_of_corners(frame_box, r_);
}

double RotatedSurface::value(const Vec3& p) const {
  return surface_.value(r_ * p);
}

void RotatedSurface::values(std::span<const Vec3> points, std::span<double> out) const {
  std::vector<Vec3> user(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) user[i] = r_ * points[i];
  surface_.values(user, out);
}

ValueGradient RotatedSurface::value_gradient(const Vec3& p) const {
  ValueGradient vg = surface_.value_gradient(r_ * p);
  vg.gradient = r_.transpose() * vg.gradient;
  return vg;
}

SecondOrder RotatedSurface::second_order(const Vec3& p) const {
  SecondOrder s = surface_.second_order(r_ * p);
  s.gradient = r_.transpose() * s.gradient;
  s.hessian = r_.transpose() * s.hessian * r_;
  return s;
}

std::optional<Interval> RotatedSurface::bound(const Box& box) const {
  return surface_.bound(user_box(box));
}

std::optional<IntervalGradient> RotatedSurface::gradient_bound(const Box& box) const {
  const auto g = surface_.gradient_bound(user_box(box));
  if (!g) return g;
  IntervalGradient out;
  out.value = g->value;
  for (int i = 0; i < 3; ++i) {
    double lo = 0.0, hi = 0.0, scale = 0.0;
    for (int j = 0; j < 3; ++j) {
      const double w = r_(j, i);  // (R^T)_ij
      const Interval& gj = g->gradient[static_cast<std::size_t>(j)];
      if (gj.empty()) {
        lo = hi = std::numeric_limits<double>::quiet_NaN();  // f is NaN on the box: an empty bound
        break;
      }
      if (w == 0.0) continue;
      const double a = w * gj.lo, b = w * gj.hi;
      lo += std::min(a, b);
      hi += std::max(a, b);
      scale = std::max({scale, std::abs(a), std::abs(b)});
    }
    const double pad = 16.0 * std::numeric_limits<double>::epsilon() * scale;  // rounding of the sums
    out.gradient[static_cast<std::size_t>(i)] = Interval{lo - pad, hi + pad};
  }
  return out;
}

}  // namespace isopatch
