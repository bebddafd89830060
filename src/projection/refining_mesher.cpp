// The projection mesher's refinement loop (refining_mesher.hpp).
#include "projection/refining_mesher.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "core/stage_timer.hpp"
#include "projection/cell_mesher.hpp"
#include "projection/cell_sizing.hpp"
#include "projection/doubtful_cells.hpp"
#include "projection/raw_defects.hpp"
#include "projection/refinement_rounds.hpp"

namespace isopatch {
namespace {

/// Rounds of local refinement before failing cells are closed by fans: a bound on the passes (each
/// meshes the whole partition). A rejected cell goes one level deeper per round, so this reaches the
/// default limit (3 levels below the start) with room for cells that fail only once a neighbour is split.
constexpr int kMaxRounds = 8;

ProjectionStats projection_stats(const CellPartition& partition, const CellMesher& mesher,
                                 const CellMesherCounters& counters, const PatchSettings& patch,
                                 int max_level, std::size_t refinements, std::size_t curvature_steps) {
  ProjectionStats p;
  p.start_depth = partition.start_level;
  p.depth_limit = max_level;
  p.resolution = patch.resolution;
  std::tie(p.side_segments_min, p.side_segments_max) = mesher.segment_range();
  p.patches_by_sides = counters.patches_by_sides;
  p.rejected_patches = counters.rejected_patches;
  p.rejected_sides = counters.rejected_sides;
  p.refined_patches = counters.refined_patches;
  p.fallback_cells = counters.fallback_cells;
  p.unprojected_vertices = counters.unprojected_vertices;
  p.gradient_rays = counters.patch.gradient_rays;
  p.clamped_base_points = counters.patch.clamped_base_points;
  p.refinements = refinements;
  p.curvature_depth_steps = curvature_steps;
  p.flat_corner_cells = partition.stats.leaves_with_flat_corners;
  for (int d = 0; d <= kMaxPartitionLevel; ++d)
    if (const std::uint64_t n = partition.stats.leaves_per_depth[static_cast<std::size_t>(d)]; n > 0)
      p.cells_by_depth[d] = n;
  p.coons_base = patch.base == PatchSettings::Base::Coons;
  return p;
}

void record_doubts(const DoubtfulCells& doubtful, int max_level, MeshWarnings& w) {
  w.doubtful_cells = doubtful.count;
  w.doubtful_topology_cells = doubtful.topology;
  w.doubtful_grazing_faces = doubtful.grazing_faces;
  w.doubtful_cell_size = doubtful.largest_side;
  w.depth_limit = max_level;
  for (int r = 0; r < kComplexReasonCount; ++r)
    if (const std::size_t n = doubtful.by_reason[static_cast<std::size_t>(r)]; n > 0)
      w.doubtful_cells_by_reason[to_string(static_cast<ComplexReason>(r))] = n;
}

}  // namespace

Mesh mesh_refining(const Surface& surface, Partitioner& partitioner, const OctreeSettings& octree,
                   const CellMesherSettings& settings, const TargetSizes& sizes, MeshStats* stats) {
  const BudgetSettings& budget = settings.budget;
  const int resolution = settings.patch.resolution;
  const Sampler f(surface);
  CellMesherCounters counters;
  std::uint64_t partition_values = 0, partition_gradients = 0;
  std::size_t curvature_steps = 0;
  bool start_settled = false;
  const int max_level = partitioner.max_level();
  const std::function<double(const Vec3&)> size_at = size_function(surface, sizes);
  StageTimes* times = stats ? &stats->times : nullptr;
  // Restarts at a finer level do not count as rounds: only refinements do. Splits for a size field are
  // counted apart (size_rounds): each deepens the finest cells that are too large by one level, so there
  // are at most max_level of them, and a field that asks for cells many levels down (a thin rim) leaves
  // the rounds for rejected patches untouched.
  int size_rounds = 0;
  std::size_t rounds = 0;
  std::optional<CellPartition> partition;
  std::optional<CellMesher> mesher;
  Mesh mesh;
  // One pass of the refinement loop: the partition built (restarting finer, unseen by the loop, while
  // it is empty, too curved or too coarse for the size field), then every cell meshed.
  const auto pass = [&](bool close_rejected) {
    for (;;) {
      budget.check_cancel();
      mesher.reset();
      partition = [&] {
        const StageTimer timer(times, "partition");
        return partitioner.build();
      }();
      partition_values += partition->stats.value_evaluations;
      partition_gradients += partition->stats.gradient_evaluations;
      if (budget.progress) budget.progress(Progress{rounds, static_cast<std::size_t>(kMaxRounds)});
      const int start = partition->start_level;
      if (partition->cells.empty()) {
        // Nothing found yet: look finer (cheap where intervals or the heuristic prune).
        if (!partitioner.start_finer())
          throw NoSurfaceError("no surface in the box: f = 0 crosses no cell down to depth " +
                               std::to_string(start));
        continue;
      }
      // With automatic resolution, patches should not wrap around the surface's tubes: while most of
      // the starting cells are too curved, start one level deeper (once per level, before any split).
      if (!start_settled) {
        start_settled =
            resolution != 0 || octree.max_cell_curvature == 0.0 || start >= max_level ||
            !starting_cells_too_curved(*partition, surface, start, octree.max_cell_curvature, size_at);
        if (!start_settled && partitioner.start_finer()) {
          ++curvature_steps;
          continue;
        }
        start_settled = true;
      }
      // Cells whose topology is in doubt (two sheets, an ambiguous face) are split by the partition down
      // to its finest level: a coarser fan there would give a closed mesh of the wrong topology. Rejected
      // patches are refined at most refinement_levels below the start (a size field: to the finest level).
      const int patch_level =
          std::max(start, sizes.varies() ? max_level : std::min(max_level, start + octree.refinement_levels));
      if (sizes.varies() && size_rounds <= max_level) {
        // The size field asks for cells of at most kAutoSegments local edge lengths.
        if (const std::vector<std::size_t> split = cells_too_large_for(*partition, size_at, patch_level);
            !split.empty()) {
          partitioner.split(split);
          ++size_rounds;
          continue;
        }
      }
      // The last pass closes whatever still fails by fans.
      mesher.emplace(f, *partition, settings, resolution, close_rejected ? 0 : patch_level, size_at,
                     !sizes.varies());
      counters.start_pass();
      mesh = mesher->run(counters, times);
      return mesher->to_split();
    }
  };
  const auto refine = [&](const std::vector<std::size_t>& split) {
    partitioner.split(split);
    ++rounds;
    return true;
  };
  // The octree always splits (refine never returns false), and its mesher closes cells only in a whole
  // pass: close re-runs one.
  const auto close = [&](const std::vector<std::size_t>&) {
    budget.check_cancel();
    pass(true);
  };
  refine_until_accepted(kMaxRounds, pass, refine, close, [&] { budget.check_cancel(); });
  const DoubtfulCells doubtful = [&] {
    const StageTimer timer(times, "checks");
    return doubtful_cells(*partition, partitioner, f);
  }();
  mesh.triangles.shrink_to_fit();
  if (stats) {
    stats->value_evaluations = partition_values + f.value_count();
    stats->gradient_evaluations = partition_gradients + f.gradient_count();
    stats->vertices = mesh.vertex_count();
    stats->triangles = mesh.triangle_count();
    stats->projection = projection_stats(*partition, *mesher, counters, settings.patch, max_level,
                                         rounds + static_cast<std::size_t>(size_rounds), curvature_steps);
    record_doubts(doubtful, max_level, stats->warnings);
    const StageTimer timer(times, "defects");
    stats->projection->defects = raw_defects(mesh, mesher->roles(), sizes.largest);
  }
  return mesh;
}

}  // namespace isopatch
