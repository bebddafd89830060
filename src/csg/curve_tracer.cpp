/// \file curve_tracer.cpp
/// Predictor-corrector tracing of a = b = 0 (curve_tracer.hpp).
#include "csg/curve_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "surface/curve_point.hpp"

namespace isopatch {

namespace {

/// The tangent may turn by at most this much per step (cos of 10 degrees): the polyline then follows
/// the curve to a chord error below 0.4% of a step.
constexpr double kTurnCosine = 0.9848;
/// The step is halved at most this many times before the curve counts as lost.
constexpr int kHalvings = 12;

}  // namespace

Vec3 curve_tangent(const Surface& a, const Surface& b, const Vec3& p) {
  const Vec3 t = a.value_gradient(p).gradient.cross(b.value_gradient(p).gradient);
  const double n = t.norm();
  return n > 0.0 && std::isfinite(n) ? Vec3(t / n) : Vec3::Zero();
}

TracedPath trace_curve(const Surface& a, const Surface& b, const Vec3& start, double sign,
                       const TraceParams& params) {
  TracedPath path;
  path.points.push_back(start);
  Vec3 p = start;
  Vec3 t = sign * curve_tangent(a, b, p);
  if (t.isZero()) return path;
  bool far_from_start = false;
  Box grown = params.box;
  const Vec3 margin = Vec3::Constant(1e-9 * params.box.diagonal());
  grown.lo -= margin;
  grown.hi += margin;
  while (path.points.size() < params.max_points) {
    double s = params.step;
    std::optional<Vec3> next;
    Vec3 next_t = Vec3::Zero();
    for (int h = 0; h <= kHalvings && !next; ++h, s *= 0.5) {
      CurvePointParams cp;
      cp.tolerance = params.tolerance;
      cp.max_step = s;
      cp.max_travel = s;
      const std::optional<Vec3> q = settle_on_curve(a, b, p + s * t, cp);
      if (!q) continue;
      const Vec3 qt = curve_tangent(a, b, *q);
      const double d = (*q - p).norm();
      if (qt.isZero() || std::abs(qt.dot(t)) < kTurnCosine || d < 0.25 * s || (*q - p).dot(t) <= 0.0)
        continue;
      next = q;
      next_t = qt.dot(t) > 0.0 ? qt : Vec3(-qt);
    }
    if (!next) {
      path.end = TraceEnd::Lost;
      return path;
    }
    const Vec3 q = *next;
    // Back at the start: a closed loop.
    const double to_start = (q - start).norm();
    if (far_from_start && to_start <= 1.01 * params.step && (start - p).dot(t) > 0.0) {
      path.points.push_back(start);
      path.end = TraceEnd::Closed;
      return path;
    }
    if (to_start > 2.0 * params.step) far_from_start = true;
    // A step that passes a target ends there.
    for (const Vec3& target : params.targets) {
      if ((target - start).norm() < 1e-9 * params.step) continue;
      const Vec3 d = q - p;
      const double u = std::clamp((target - p).dot(d) / d.squaredNorm(), 0.0, 1.0);
      if ((p + u * d - target).norm() <= 1e-3 * s) {
        path.points.push_back(target);
        path.end = TraceEnd::Corner;
        path.third = -1;
        return path;
      }
    }
    if (!grown.contains(q)) {
      path.end = TraceEnd::Box;
      return path;
    }
    const int third = params.owner(q);
    if (third >= 0) {
      // The curve leaves its part of the shape between p and q: the corner where the third face's
      // function vanishes too.
      const Surface& c = params.third_function(third);
      CurvePointParams cp;
      cp.tolerance = params.tolerance;
      cp.max_step = 2.0 * s;
      cp.max_travel = 4.0 * s;
      std::optional<Vec3> corner = settle_on_corner(a, b, c, p, cp);
      if (!corner) corner = settle_on_corner(a, b, c, q, cp);
      if (!corner) corner = settle_on_corner(a, b, c, 0.5 * (p + q), cp);
      if (!corner) {
        path.end = TraceEnd::Lost;
        return path;
      }
      // Points the corner falls behind (it may lie before p) are dropped, so the polyline runs on.
      while (path.points.size() > 1 && (*corner - path.points.back()).dot(t) <= 0.0) path.points.pop_back();
      path.points.push_back(*corner);
      path.end = TraceEnd::Corner;
      path.third = third;
      return path;
    }
    path.points.push_back(q);
    p = q;
    t = next_t;
  }
  path.end = TraceEnd::Lost;
  return path;
}

}  // namespace isopatch
