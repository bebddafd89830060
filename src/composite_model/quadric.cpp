/// \file quadric.cpp
/// Quadric ribbons and bounding functions (quadric.hpp).
#include "composite_model/quadric.hpp"

#include <isopatch/error.hpp>
#include <isopatch/interval_math.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace isopatch {

Affine plane_through(const Vec3& point, const Vec3& normal) {
  const double length = normal.norm();
  if (!(length > 0.0) || !std::isfinite(length) || !point.allFinite()) {
    throw InputError("a plane needs a finite point and a non-zero normal");
  }
  const Vec3 n = normal / length;
  return {n, -n.dot(point)};
}

Quadric Quadric::from(const Affine& f) {
  return {Mat3::Zero(), f.n, f.d};
}

Quadric Quadric::product(const Affine& f, const Affine& g) {
  const Mat3 outer = f.n * g.n.transpose();
  return {0.5 * (outer + outer.transpose()), f.d * g.n + g.d * f.n, f.d * g.d};
}

Quadric liming_quadric(const Affine& l1, const Affine& l2, const Affine& l3, double lambda, double sigma) {
  return (Quadric::product(l1, l2) - Quadric::product(l3, l3) * lambda) * sigma;
}

Quadric ball_cylinder(const Vec3& point, const Vec3& direction, double r) {
  const double length = direction.norm();
  if (!(r > 0.0) || !std::isfinite(r) || !(length > 0.0) || !point.allFinite()) {
    throw InputError("a blend cylinder needs a positive radius and an axis direction");
  }
  const Vec3 e = direction / length;
  // |x - p|^2 - (e.(x - p))^2 = (x - p)'(I - e e')(x - p).
  const Mat3 m = Mat3::Identity() - e * e.transpose();
  Quadric q{m, -2.0 * (m * point), point.dot(m * point) - r * r};
  return q * (0.5 / r);
}

namespace {

std::array<Interval, 3> box_intervals(const Box& box) {
  return {Interval{box.lo.x(), box.hi.x()}, Interval{box.lo.y(), box.hi.y()},
          Interval{box.lo.z(), box.hi.z()}};
}

Interval point(double v) {
  return {v, v};
}

}  // namespace

std::optional<Interval> QuadricSurface::bound(const Box& box) const {
  const auto x = box_intervals(box);
  Interval sum = point(q_.c);
  for (int i = 0; i < 3; ++i) {
    sum = sum + point(q_.a(i, i)) * sqr(x[i]) + point(q_.b(i)) * x[i];
    for (int j = i + 1; j < 3; ++j) sum = sum + point(2.0 * q_.a(i, j)) * (x[i] * x[j]);
  }
  return sum;
}

std::optional<IntervalGradient> QuadricSurface::gradient_bound(const Box& box) const {
  const auto x = box_intervals(box);
  IntervalGradient out;
  out.value = *bound(box);
  for (int i = 0; i < 3; ++i) {
    Interval g = point(q_.b(i));
    for (int j = 0; j < 3; ++j) g = g + point(2.0 * q_.a(i, j)) * x[j];
    out.gradient[i] = g;
  }
  return out;
}

MaxSurface::MaxSurface(std::string name, Box box, SurfacePtr f, SurfacePtr g)
    : Surface(std::move(name), box), f_(std::move(f)), g_(std::move(g)) {
  if (!f_ || !g_) throw InputError("a union bound needs two functions");
}

double MaxSurface::value(const Vec3& p) const {
  return std::max(f_->value(p), g_->value(p));
}

ValueGradient MaxSurface::value_gradient(const Vec3& p) const {
  const ValueGradient a = f_->value_gradient(p);
  const ValueGradient b = g_->value_gradient(p);
  return b.value > a.value ? b : a;
}

SecondOrder MaxSurface::second_order(const Vec3& p) const {
  const SecondOrder a = f_->second_order(p);
  const SecondOrder b = g_->second_order(p);
  return b.value > a.value ? b : a;
}

std::optional<Interval> MaxSurface::bound(const Box& box) const {
  const auto a = f_->bound(box);
  const auto b = g_->bound(box);
  if (!a || !b) return std::nullopt;
  return Interval{std::max(a->lo, b->lo), std::max(a->hi, b->hi)};
}

std::optional<IntervalGradient> MaxSurface::gradient_bound(const Box& box) const {
  const auto a = f_->gradient_bound(box);
  const auto b = g_->gradient_bound(box);
  if (!a || !b) return std::nullopt;
  IntervalGradient out;
  out.value = Interval{std::max(a->value.lo, b->value.lo), std::max(a->value.hi, b->value.hi)};
  // The gradient is one of the two (whichever is larger), so the hull of both holds it.
  for (int i = 0; i < 3; ++i) out.gradient[i] = hull(a->gradient[i], b->gradient[i]);
  return out;
}

}  // namespace isopatch
