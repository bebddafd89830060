/// \file curve_point.cpp
/// Newton iterations onto two or three functions (curve_point.hpp).
#include "surface/curve_point.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace isopatch {

namespace {

/// Below this sine between two gradients the pair has no well-defined curve (tangential contact).
constexpr double kParallelSine = 1e-6;

bool settled_within(const ValueGradient& g, double tolerance) {
  const double n = g.gradient.norm();
  return n > 0.0 && std::abs(g.value) <= tolerance * n;
}

bool all_finite(const ValueGradient& g) {
  return std::isfinite(g.value) && g.gradient.allFinite();
}

Vec3 limited(const Vec3& step, double max_step) {
  const double n = step.norm();
  return n > max_step ? step * (max_step / n) : step;
}

}  // namespace

std::optional<Vec3> settle_on_curve(const Surface& a, const Surface& b, const Vec3& start,
                                    const CurvePointParams& params) {
  Vec3 x = start;
  for (int it = 0; it <= params.max_iterations; ++it) {
    const ValueGradient ga = a.value_gradient(x), gb = b.value_gradient(x);
    if (!all_finite(ga) || !all_finite(gb)) return std::nullopt;
    if (settled_within(ga, params.tolerance) && settled_within(gb, params.tolerance)) return x;
    if (it == params.max_iterations) break;
    const double na = ga.gradient.norm(), nb = gb.gradient.norm();
    if (!(na > 0.0) || !(nb > 0.0) || ga.gradient.cross(gb.gradient).norm() < kParallelSine * na * nb)
      return std::nullopt;
    Eigen::Matrix<double, 2, 3> j;
    j.row(0) = ga.gradient.transpose();
    j.row(1) = gb.gradient.transpose();
    const Eigen::Matrix2d jjt = j * j.transpose();
    const Eigen::Vector2d r(ga.value, gb.value);
    const Vec3 step = -(j.transpose() * jjt.ldlt().solve(r));
    if (!step.allFinite()) return std::nullopt;
    x += limited(step, params.max_step);
    if ((x - start).norm() > params.max_travel) return std::nullopt;
  }
  return std::nullopt;
}

std::optional<Vec3> settle_on_corner(const Surface& a, const Surface& b, const Surface& c, const Vec3& start,
                                     const CurvePointParams& params) {
  Vec3 x = start;
  for (int it = 0; it <= params.max_iterations; ++it) {
    const ValueGradient ga = a.value_gradient(x), gb = b.value_gradient(x), gc = c.value_gradient(x);
    if (!all_finite(ga) || !all_finite(gb) || !all_finite(gc)) return std::nullopt;
    if (settled_within(ga, params.tolerance) && settled_within(gb, params.tolerance) &&
        settled_within(gc, params.tolerance))
      return x;
    if (it == params.max_iterations) break;
    Eigen::Matrix3d j;
    j.row(0) = ga.gradient.transpose();
    j.row(1) = gb.gradient.transpose();
    j.row(2) = gc.gradient.transpose();
    const double scale = ga.gradient.norm() * gb.gradient.norm() * gc.gradient.norm();
    if (!(std::abs(j.determinant()) > kParallelSine * scale)) return std::nullopt;
    const Vec3 step = -j.partialPivLu().solve(Eigen::Vector3d(ga.value, gb.value, gc.value));
    if (!step.allFinite()) return std::nullopt;
    x += limited(step, params.max_step);
    if ((x - start).norm() > params.max_travel) return std::nullopt;
  }
  return std::nullopt;
}

double gradient_sine(const Surface& a, const Surface& b, const Vec3& p) {
  const Vec3 ga = a.value_gradient(p).gradient, gb = b.value_gradient(p).gradient;
  const double n = ga.norm() * gb.norm();
  return n > 0.0 ? std::min(1.0, ga.cross(gb).norm() / n) : 0.0;
}

}  // namespace isopatch
