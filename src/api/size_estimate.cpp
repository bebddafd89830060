// The output size and largest curvature estimated up front (size_estimate.hpp).
#include "api/size_estimate.hpp"

#include <isopatch/error.hpp>
#include <isopatch/level_set_curvature.hpp>
#include <isopatch/marching_cubes.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace isopatch {

SizeEstimate estimate_size(const Surface& surface, const Settings& settings, const Box& box,
                           bool with_curvature) {
  Settings grid;
  grid.method = Method::MarchingCubes;
  grid.box = box;
  grid.grid = kEstimateGrid;
  grid.edge_root = EdgeRoot::Linear;
  grid.cancel = settings.cancel;
  MeshStats stats;
  const Mesh mesh = marching_cubes(surface, grid, &stats);
  SizeEstimate estimate;
  estimate.value_evaluations = stats.value_evaluations;
  double area = 0.0;
  for (const Triangle& t : mesh.triangles)
    area += 0.5 * (mesh.positions[t[1]] - mesh.positions[t[0]])
                      .cross(mesh.positions[t[2]] - mesh.positions[t[0]])
                      .norm();
  const double h = default_edge_length(settings, box);
  estimate.vertices = 2.0 * area / (std::sqrt(3.0) * h * h);
  if (with_curvature) {
    // Linear roots on the grid's edges lie off f = 0 by up to a fraction of a cell, where the level set
    // through them bends more or less than f = 0 (inside a thin tube, much more): two Newton steps along
    // grad f first, each at most a cell long.
    const double cell = box.size().maxCoeff() / kEstimateGrid;
    for (Vec3 p : mesh.positions) {
      for (int step = 0; step < kEstimateNewtonSteps; ++step) {
        const ValueGradient vg = surface.value_gradient(p);
        const double g2 = vg.gradient.squaredNorm();
        if (!(g2 > 0.0) || !std::isfinite(vg.value)) break;
        const Vec3 move = -vg.value / g2 * vg.gradient;
        if (!(move.norm() <= cell)) break;
        p += move;
      }
      const double kappa = max_abs_principal_curvature(surface, p);
      if (std::isfinite(kappa)) estimate.largest_curvature = std::max(estimate.largest_curvature, kappa);
    }
    estimate.gradient_evaluations = (1 + kEstimateNewtonSteps) * mesh.vertex_count();
  }
  return estimate;
}

void check_estimated_size(const SizeEstimate& estimate, const Settings& settings, const Box& box) {
  if (settings.max_vertices == 0 || estimate.vertices <= static_cast<double>(settings.max_vertices)) return;
  char text[256];
  std::snprintf(text, sizeof text,
                "the mesh would have about %.3g vertices at edge length %.3g, more than the vertex budget of "
                "%zu: give a longer edge length or a larger budget",
                estimate.vertices, default_edge_length(settings, box), settings.max_vertices);
  throw LimitError(text, "max_vertices");
}

}  // namespace isopatch
