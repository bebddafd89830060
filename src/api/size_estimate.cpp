// The output size estimated up front (size_estimate.hpp).
#include "api/size_estimate.hpp"

#include <isopatch/error.hpp>
#include <isopatch/marching_cubes.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace isopatch {

double estimated_vertices(const Surface& surface, const Settings& settings, const Box& box,
                          std::uint64_t* evaluations) {
  Settings grid;
  grid.method = Method::MarchingCubes;
  grid.box = box;
  grid.grid = kEstimateGrid;
  grid.edge_root = EdgeRoot::Linear;
  grid.cancel = settings.cancel;
  MeshStats stats;
  const Mesh mesh = marching_cubes(surface, grid, &stats);
  if (evaluations) *evaluations = stats.value_evaluations;
  double area = 0.0;
  for (const Triangle& t : mesh.triangles)
    area += 0.5 * (mesh.positions[t[1]] - mesh.positions[t[0]])
                      .cross(mesh.positions[t[2]] - mesh.positions[t[0]])
                      .norm();
  const double h = default_edge_length(settings, box);
  return 2.0 * area / (std::sqrt(3.0) * h * h);
}

std::uint64_t check_estimated_size(const Surface& surface, const Settings& settings, const Box& box) {
  if (settings.max_vertices == 0) return 0;
  std::uint64_t evaluations = 0;
  const double estimate = estimated_vertices(surface, settings, box, &evaluations);
  if (estimate <= static_cast<double>(settings.max_vertices)) return evaluations;
  char text[256];
  std::snprintf(text, sizeof text,
                "the mesh would have about %.3g vertices at edge length %.3g, more than the vertex budget of "
                "%zu: give a longer edge length or a larger budget",
                estimate, default_edge_length(settings, box), settings.max_vertices);
  throw LimitError(text, "max_vertices");
}

}  // namespace isopatch
