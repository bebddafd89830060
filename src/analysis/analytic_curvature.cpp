// Exact curvature of level sets (Goldman 2005) and the per-vertex fields built from it.
#include <isopatch/curvature.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

#include "mesh_neighbourhood.hpp"

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

std::vector<float> to_float(const std::vector<double>& values) {
  std::vector<float> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) out[i] = static_cast<float>(values[i]);
  return out;
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

CurvatureFields curvature_fields(const Mesh& mesh, const Surface& surface) {
  DiscreteCurvature discrete = discrete_curvature(mesh);  // checks the mesh
  const std::size_t n = mesh.positions.size();
  CurvatureFields fields;
  fields.mean_discrete = std::move(discrete.mean);
  fields.gauss_discrete = std::move(discrete.gaussian);
  fields.mean_analytic.assign(n, 0.0);
  fields.gauss_analytic.assign(n, 0.0);
  fields.distance.assign(n, 0.0);
  for (std::size_t v = 0; v < n; ++v) {
    const SecondOrder s = surface.second_order(mesh.positions[v]);
    const PointCurvature c = analytic_curvature(s);
    fields.mean_analytic[v] = c.mean;
    fields.gauss_analytic[v] = c.gaussian;
    fields.distance[v] = s.value / s.gradient.norm();  // NaN or inf where grad f = 0: left visible
  }
  return fields;
}

void attach_fields(Mesh& mesh, const Surface& surface) {
  const CurvatureFields fields = curvature_fields(mesh, surface);
  mesh.set_attribute("mean_curvature", to_float(fields.mean_discrete));
  mesh.set_attribute("mean_curvature_exact", to_float(fields.mean_analytic));
  mesh.set_attribute("gaussian_curvature", to_float(fields.gauss_discrete));
  mesh.set_attribute("gaussian_curvature_exact", to_float(fields.gauss_analytic));
  mesh.set_attribute("distance", to_float(fields.distance));
}

}  // namespace isopatch
