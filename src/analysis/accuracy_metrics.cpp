// Accuracy of a mesh against its implicit surface (docs/algorithms.md 7.2): first-order
// distance, normal errors and curvature errors, with f's exact derivatives as the ground truth.
// Samples where the truth is undefined (grad f = 0, non-finite f) or the mesh has no normal are
// counted, never silently mixed in.
#include <isopatch/curvature.hpp>
#include <isopatch/metrics.hpp>

#include <cmath>
#include <limits>
#include <numbers>

#include "mesh_neighbourhood.hpp"

namespace isopatch {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

bool usable(const ValueGradient& vg) {
  return std::isfinite(vg.value) && vg.gradient.allFinite() && vg.gradient.squaredNorm() > 0.0;
}

CurvatureError compare(const std::vector<double>& discrete, const std::vector<double>& exact,
                       const std::vector<bool>& interior) {
  CurvatureError e;
  std::vector<double> errors;
  double error_squares = 0.0;
  double exact_squares = 0.0;
  for (std::size_t v = 0; v < discrete.size(); ++v) {
    if (!interior[v]) continue;
    if (!std::isfinite(discrete[v]) || !std::isfinite(exact[v])) {
      ++e.undefined;
      continue;
    }
    const double d = discrete[v] - exact[v];
    errors.push_back(std::abs(d));
    error_squares += d * d;
    exact_squares += exact[v] * exact[v];
  }
  e.vertices = errors.size();
  e.nrms =
      errors.empty() ? std::numeric_limits<double>::quiet_NaN() : std::sqrt(error_squares / exact_squares);
  e.abs_error = summarize(std::move(errors));
  return e;
}

}  // namespace

AccuracyReport analyze_accuracy(const Mesh& mesh, const Surface& surface) {
  analysis::check_mesh(mesh, "analyze_accuracy");
  AccuracyReport report;
  report.diagonal = mesh.positions.empty() ? 0.0 : bounding_box(mesh).diagonal();

  // Vertices: distance, vertex normal, exact curvature from one second-order evaluation each.
  const std::vector<Vec3> normals = analysis::area_weighted_normals(mesh);
  const std::size_t n = mesh.positions.size();
  std::vector<double> mean_exact(n), gauss_exact(n);
  std::vector<double> vertex_distance, vertex_normal;
  vertex_distance.reserve(n);
  vertex_normal.reserve(n);
  for (std::size_t v = 0; v < n; ++v) {
    const SecondOrder s = surface.second_order(mesh.positions[v]);
    const PointCurvature c = analytic_curvature(s);
    mean_exact[v] = c.mean;
    gauss_exact[v] = c.gaussian;
    if (!usable({s.value, s.gradient})) {
      ++report.undefined_samples;
      continue;
    }
    vertex_distance.push_back(std::abs(s.value) / s.gradient.norm());
    if (normals[v].squaredNorm() > 0.0)
      vertex_normal.push_back(analysis::angle_between(normals[v], s.gradient) * kDegrees);
    else
      ++report.undefined_samples;  // unreferenced, or only zero-area triangles
  }

  // Triangles: chordal distance and facet normal at the centroid.
  std::vector<double> centroid_distance, triangle_normal;
  centroid_distance.reserve(mesh.triangles.size());
  triangle_normal.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.positions[t[0]];
    const Vec3& b = mesh.positions[t[1]];
    const Vec3& c = mesh.positions[t[2]];
    const ValueGradient vg = surface.value_gradient((a + b + c) / 3.0);
    if (!usable(vg)) {
      ++report.undefined_samples;
      continue;
    }
    centroid_distance.push_back(std::abs(vg.value) / vg.gradient.norm());
    const Vec3 normal = (b - a).cross(c - a);
    if (normal.squaredNorm() > 0.0)
      triangle_normal.push_back(analysis::angle_between(normal, vg.gradient) * kDegrees);
    else
      ++report.undefined_samples;
  }
  report.vertex_distance = summarize(std::move(vertex_distance));
  report.vertex_normal_error = summarize(std::move(vertex_normal));
  report.centroid_distance = summarize(std::move(centroid_distance));
  report.triangle_normal_error = summarize(std::move(triangle_normal));

  const DiscreteCurvature discrete = discrete_curvature(mesh);
  report.mean_curvature = compare(discrete.mean, mean_exact, discrete.interior);
  report.gaussian_curvature = compare(discrete.gaussian, gauss_exact, discrete.interior);
  return report;
}

}  // namespace isopatch
