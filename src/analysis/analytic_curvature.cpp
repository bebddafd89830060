// Per-vertex fields of exact (src/surface/level_set_curvature.cpp) and discrete curvature.
#include <isopatch/curvature.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh_neighbourhood.hpp"

namespace isopatch {
namespace {

std::vector<float> to_float(const std::vector<double>& values) {
  std::vector<float> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) out[i] = static_cast<float>(values[i]);
  return out;
}

}  // namespace

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
