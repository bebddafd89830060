// mesh_projection() (include/isopatch/projection.hpp): checks the settings, plans the octree's depths
// from the target edge length, and runs the refining mesher over it. The one place that chooses the
// kind of partition (the octree, or convex cells for a region or given cells: convex_meshing.hpp); the
// mesher itself sees only cell_partition.hpp.
#include <isopatch/error.hpp>
#include <isopatch/projection.hpp>

#include <chrono>
#include <cmath>
#include <string>

#include "partition/convex_partitioner.hpp"
#include "partition/octree_partitioner.hpp"
#include "projection/cell_sizing.hpp"
#include "projection/convex_meshing.hpp"
#include "projection/refining_mesher.hpp"

namespace isopatch {
namespace {

/// The finest cells a size field may need, in its smallest sizes: two, so that where it asks for its
/// smallest size (around a rim of radius about twice that) a cell can hold the rim's turn alone.
constexpr double kFinestCellSizes = 2.0;

/// With a fixed resolution r: the depth whose cells are closest (in log scale) to r edge lengths, and
/// max_depth as the limit. With automatic resolution: the coarsest depth whose cells are at most
/// kAutoSegments edges long; when that is max_depth or deeper, the limit is raised by
/// refinement_levels. A size field's smallest_size deepens the limit to cells of kFinestCellSizes of it.
OctreeDepths octree_depths(const SizeSettings& sizes, const PatchSettings& patch, const OctreeSettings& s,
                           const Box& box) {
  const double edge = default_edge_length(sizes, box);
  OctreeDepthRequest request;
  request.closest = patch.resolution > 0;
  request.cell_length = edge * (patch.resolution > 0 ? patch.resolution : kAutoSegments);
  request.min_depth = s.min_depth;
  request.max_depth = s.max_depth;
  request.raise_limit_by = patch.resolution != 0 ? -1 : s.refinement_levels;
  if (sizes.size_field && sizes.smallest_size) request.finest_cell = kFinestCellSizes * *sizes.smallest_size;
  return plan_octree_depths(box, request);
}

/// The convex partitioner of a region or of given cells over `box`: a region's cubes start at the
/// octree's depths; given cells start whole and may be split refinement_levels + 4 times.
ConvexPartitioner convex_partitioner(const Surface& surface, const Settings& settings, const Box& box) {
  ConvexPartitionerSettings s;
  s.cancel = settings.cancel;
  if (!settings.region.empty()) {
    const OctreeDepths depths = octree_depths(settings, settings, settings, box);
    s.start_level = depths.start;
    s.max_level = depths.limit;
    return ConvexPartitioner::clipped_lattice(surface, box, cell_planes(settings.region), s);
  }
  s.start_level = 0;
  s.max_level = std::min(kMaxPartitionLevel, settings.refinement_levels + 4);
  std::vector<std::vector<CellPlane>> cells;
  for (const ConvexRegion& c : settings.cells) cells.push_back(cell_planes(c));
  return ConvexPartitioner::given_cells(surface, box, cells, s);
}

}  // namespace

Mesh mesh_projection(const Surface& surface, const Settings& settings, MeshStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  // The stages this mesher runs check their own settings.
  settings.SizeSettings::validate();
  settings.OctreeSettings::validate();
  settings.PatchSettings::validate();
  settings.ProjectionSettings::validate();
  settings.BudgetSettings::validate();
  const std::optional<Box> convex = convex_meshing_box(surface, settings);
  const Box box = convex ? *convex : valid_box(settings.box.value_or(surface.box()));
  const CellMesherSettings stages{settings, settings, settings};
  Mesh mesh;
  if (convex) {
    try {
      ConvexPartitioner partitioner = convex_partitioner(surface, settings, box);
      mesh = mesh_refining(surface, partitioner, settings, stages, target_sizes(settings, box), stats);
    } catch (const SettingError&) {
      throw;
    } catch (const InputError& e) {
      // Cells that overlap or leave gaps are the caller's cells' fault.
      if (settings.cells.empty()) throw;
      throw SettingError("cells", e.what());
    }
  } else {
    const OctreeDepths depths = octree_depths(settings, settings, settings, box);
    PartitionSettings octree;
    octree.surface_depth = depths.start;
    octree.max_depth = depths.limit;
    octree.cancel = settings.cancel;
    OctreePartitioner partitioner(surface, box, octree);
    mesh = mesh_refining(surface, partitioner, settings, stages, target_sizes(settings, box), stats);
  }
  if (stats) stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return mesh;
}

}  // namespace isopatch
