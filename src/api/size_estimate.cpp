// The output size and largest curvature estimated up front (size_estimate.hpp).
#include "api/size_estimate.hpp"

#include <isopatch/error.hpp>
#include <isopatch/marching_cubes.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "refine/refinement_level.hpp"
#include "surface/project_point.hpp"
#include "surface/sampler.hpp"

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
  SizeEstimate estimate;
  Mesh mesh;
  try {
    mesh = marching_cubes(surface, grid, &stats);
  } catch (const NoSurfaceError&) {
    // A surface thinner than the grid's cells (a flat ellipsoid in a flat box) crosses no grid edge
    // with a sign change; the mesher decides whether there is a surface. Nothing is estimated.
    estimate.found = false;
    const McGrid lattice = marching_cubes_grid(box, grid);
    estimate.value_evaluations = static_cast<std::uint64_t>(lattice.cells[0] + 1) *
                                 static_cast<std::uint64_t>(lattice.cells[1] + 1) *
                                 static_cast<std::uint64_t>(lattice.cells[2] + 1);
    return estimate;
  }
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
    // through them bends more or less than f = 0 (inside a thin tube, much more): each is moved onto
    // f = 0 first (steps of at most a cell); a point that does not get there, or meets f undefined on
    // the way, is measured where the grid put it (and skipped where its curvature is not finite).
    const double cell = box.size().maxCoeff() / kEstimateGrid;
    const Sampler f(surface);
    std::vector<Vec3> points = mesh.positions;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 256),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          Vec3 p = points[i];
                          try {
                            if (project_to_surface(f, p, kEstimateTolerance * cell, cell)) points[i] = p;
                          } catch (const EvaluationError&) {
                          }
                        }
                      });
    estimate.largest_curvature = refine::largest_curvature(points, surface, true);
    estimate.gradient_evaluations = f.gradient_count() + points.size();
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
