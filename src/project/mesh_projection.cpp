// mesh_projection() (include/isopatch/projection.hpp): checks the settings, plans the octree's depths
// from the target edge length, and runs the refining mesher over it. The one place that chooses the
// kind of partition; the mesher itself sees only cell_partition.hpp.
#include <isopatch/error.hpp>
#include <isopatch/projection.hpp>

#include <chrono>
#include <cmath>
#include <string>

#include "partition/octree_partitioner.hpp"
#include "patch/patch_template.hpp"
#include "project/cell_sizing.hpp"
#include "project/refining_mesher.hpp"

namespace isopatch {
namespace {

void check_settings(const Settings& s) {
  if (s.edge_length && !(std::isfinite(*s.edge_length) && *s.edge_length > 0.0))
    throw InputError("edge length must be a positive number");
  if (s.resolution != 0 &&
      (s.resolution < PatchTemplate::kMinResolution || s.resolution > PatchTemplate::kMaxResolution))
    throw InputError("resolution must be 0 (automatic) or between 1 and 64, got " +
                     std::to_string(s.resolution));
  if (s.min_depth < 0 || s.max_depth > kOctreeDepthLimit || s.min_depth > s.max_depth)
    throw InputError(
        "depths must satisfy 0 <= min-depth <= max-depth <= " + std::to_string(kOctreeDepthLimit) + ", got " +
        std::to_string(s.min_depth) + " and " + std::to_string(s.max_depth));
  if (!(s.max_ray_angle > 0.0 && s.max_ray_angle < 90.0) ||
      !(s.max_boundary_ray_angle > 0.0 && s.max_boundary_ray_angle < 90.0))
    throw InputError("acceptance angles must lie strictly between 0 and 90 degrees");
  if (s.march_steps < 4 || s.march_steps > 4096) throw InputError("march steps must be between 4 and 4096");
  if (!(std::isfinite(s.max_cell_curvature) && s.max_cell_curvature >= 0.0))
    throw InputError("the largest cell curvature must be a finite number >= 0 (0: off)");
  if (s.refinement_levels < 0 || s.refinement_levels > 12)
    throw InputError("refinement levels must be between 0 and 12");
}

/// With a fixed resolution r: the depth whose cells are closest (in log scale) to r edge lengths, and
/// max_depth as the limit. With automatic resolution: the coarsest depth whose cells are at most
/// kAutoSegments edges long; when that is max_depth or deeper, the limit is raised by
/// refinement_levels.
OctreeDepths octree_depths(const Settings& s, const Box& box) {
  const double edge = default_edge_length(s, box);
  OctreeDepthRequest request;
  request.closest = s.resolution > 0;
  request.cell_length = edge * (s.resolution > 0 ? s.resolution : kAutoSegments);
  request.min_depth = s.min_depth;
  request.max_depth = s.max_depth;
  request.raise_limit_by = s.resolution != 0 ? -1 : s.refinement_levels;
  return plan_octree_depths(box, request);
}

}  // namespace

Mesh mesh_projection(const Surface& surface, const Settings& settings, MeshStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  check_settings(settings);
  const Box box = settings.box.value_or(surface.box());
  if (!box.valid()) throw InputError("the box must have lo < hi on every axis");
  const OctreeDepths depths = octree_depths(settings, box);
  PartitionSettings octree;
  octree.surface_depth = depths.start;
  octree.max_depth = depths.limit;
  octree.cancel = settings.cancel;
  OctreePartitioner partitioner(surface, box, octree);
  Mesh mesh = mesh_refining(surface, partitioner, settings, size_spec(settings, box), stats);
  if (stats) stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return mesh;
}

}  // namespace isopatch
