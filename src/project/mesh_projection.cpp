// mesh_projection() (include/isopatch/projection.hpp): checks the settings, plans the octree's depths
// from the target edge length, and runs the refining mesher over it. The one place that chooses the
// kind of partition (the octree, or convex cells for a region or given cells: convex_meshing.hpp); the
// mesher itself sees only cell_partition.hpp.
#include <isopatch/error.hpp>
#include <isopatch/projection.hpp>

#include <chrono>
#include <cmath>
#include <string>

#include "partition/octree_partitioner.hpp"
#include "project/cell_sizing.hpp"
#include "project/convex_meshing.hpp"
#include "project/refining_mesher.hpp"

namespace isopatch {
namespace {

/// With a fixed resolution r: the depth whose cells are closest (in log scale) to r edge lengths, and
/// max_depth as the limit. With automatic resolution: the coarsest depth whose cells are at most
/// kAutoSegments edges long; when that is max_depth or deeper, the limit is raised by
/// refinement_levels.
OctreeDepths octree_depths(const SizeSettings& sizes, const PatchSettings& patch, const OctreeSettings& s,
                           const Box& box) {
  const double edge = default_edge_length(sizes, box);
  OctreeDepthRequest request;
  request.closest = patch.resolution > 0;
  request.cell_length = edge * (patch.resolution > 0 ? patch.resolution : kAutoSegments);
  request.min_depth = s.min_depth;
  request.max_depth = s.max_depth;
  request.raise_limit_by = patch.resolution != 0 ? -1 : s.refinement_levels;
  return plan_octree_depths(box, request);
}

}  // namespace

Mesh mesh_projection(const Surface& surface, const Settings& settings, MeshStats* stats) {
  if (const std::optional<Box> convex = convex_meshing_box(surface, settings))
    return mesh_convex(surface, settings, *convex, stats);
  const auto start = std::chrono::steady_clock::now();
  // The stages this mesher runs check their own settings.
  settings.SizeSettings::validate();
  settings.OctreeSettings::validate();
  settings.PatchSettings::validate();
  settings.ProjectionSettings::validate();
  settings.BudgetSettings::validate();
  const Box box = valid_box(settings.box.value_or(surface.box()));
  const OctreeDepths depths = octree_depths(settings, settings, settings, box);
  PartitionSettings octree;
  octree.surface_depth = depths.start;
  octree.max_depth = depths.limit;
  octree.cancel = settings.cancel;
  OctreePartitioner partitioner(surface, box, octree);
  const CellMesherSettings stages{settings, settings, settings};
  Mesh mesh = mesh_refining(surface, partitioner, settings, stages, target_sizes(settings, box), stats);
  if (stats) stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return mesh;
}

}  // namespace isopatch
