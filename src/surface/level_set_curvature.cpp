// Exact curvature of level sets (Goldman 2005, "Curvature formulas for implicit curves and surfaces")
// and the edge length that keeps a chordal error bound; see include/isopatch/level_set_curvature.hpp.
#include <isopatch/level_set_curvature.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace isopatch {
namespace {

// The adjugate (transposed cofactor matrix): its columns are cross products of the rows of m. It
// stays finite and meaningful when m is singular, which the inverse would not.
Mat3 adjugate(const Mat3& m) {
  const Vec3 r0 = m.row(0).transpose();
  const Vec3 r1 = m.row(1).transpose();
  const Vec3 r2 = m.row(2).transpose();
  Mat3 adj;
  adj.col(0) = r1.cross(r2);
  adj.col(1) = r2.cross(r0);
  adj.col(2) = r0.cross(r1);
  return adj;
}

}  // namespace

PointCurvature analytic_curvature(const SecondOrder& sample) {
  const Vec3& g = sample.gradient;
  const Mat3& h = sample.hessian;
  const double g2 = g.squaredNorm();
  if (!(g2 > 0.0) || !std::isfinite(g2)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan};
  }
  const double g1 = std::sqrt(g2);
  PointCurvature c;
  c.mean = (g2 * h.trace() - g.dot(h * g)) / (2.0 * g2 * g1);
  c.gaussian = g.dot(adjugate(h) * g) / (g2 * g2);
  return c;
}

PointCurvature analytic_curvature(const Surface& surface, const Vec3& p) {
  return analytic_curvature(surface.second_order(p));
}

double max_abs_principal_curvature(const Surface& surface, const Vec3& p) {
  const PointCurvature c = analytic_curvature(surface, p);
  const double k = std::abs(c.mean) + std::sqrt(std::max(c.mean * c.mean - c.gaussian, 0.0));
  return std::isfinite(k) ? k : std::numeric_limits<double>::infinity();
}

double size_for_error(double max_abs_curvature, double max_error) {
  if (!(max_abs_curvature > 0.0)) return std::numeric_limits<double>::infinity();
  // An equilateral triangle of side L on a sphere of radius R has its centroid L^2 / (6 R) below the
  // sphere; edges reach 4/3 of the target h, so h^2 (16/9) / 6 * kappa <= eps gives h <= sqrt(3.375
  // eps / kappa). sqrt(3 eps / kappa) leaves a margin for unequal triangles and varying curvature.
  return std::sqrt(3.0 * max_error / max_abs_curvature);
}

}  // namespace isopatch
