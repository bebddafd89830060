// Multiresolution meshing: a base at k times the target size, refined k times (multiresolution.hpp).
#include "api/multiresolution.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include <isopatch/error.hpp>

#include "refine/lattice_relaxation.hpp"
#include "refine/refine_mesh.hpp"
#include "refine/refinement_level.hpp"

namespace isopatch {
namespace {

/// What each quality preset asks of the refinement (docs/algorithms.md 8.4):
///   max_level     the automatic level's ceiling;
///   max_turn      the normal turn across a base edge the automatic level allows (radians, H kappa);
///   min_base      the fewest base vertices the automatic level keeps (a base of a few hundred vertices
///                 resolves too little: on the torus at 8k output vertices a 130-vertex base left twice
///                 today's curvature error, a 1000-vertex one 0.6 times it);
///   sweeps        relaxation sweeps over the whole refined mesh;
///   angle_sweeps  sweeps over the vertices near triangles under angle_target degrees.
struct RefinePreset {
  int max_level;
  double max_turn;
  double min_base;
  int sweeps;
  int angle_sweeps;
  double angle_target;
};

RefinePreset refine_preset(Quality quality) {
  switch (quality) {
    case Quality::Preview:
      return {8, 1.2, 300.0, 1, 2, 25.0};
    case Quality::Default:
      return {8, 0.8, 1000.0, 2, 4, 30.0};
    case Quality::Fine:
      // The default's refinement over a base made with the fine clean-up, up to level 12: at about 200k
      // vertices, level 12 against 8 gave H nRMS 0.00101 / 0.00173 (torus), 0.00005 / 0.00013
      // (sphere), 0.00045 / 0.00060 (ellipsoid), 0.00066 / 0.00085 (blobby) and 0.00137 / 0.00107
      // (cassini), smallest angles 25.0 to 27.0 degrees; 16 gave no less than 12 on the torus and 24.7
      // degrees. A smaller max_turn with more sweeps (0.5, 2000 base vertices, 4 + 8 sweeps) gave a
      // higher H nRMS than the default on 8 of 9 surfaces, and more sweeps alone (6, 12) a higher one
      // on the torus, tanglecube and chmutov6 (docs/algorithms.md 8.4).
      return {12, 0.8, 1000.0, 2, 4, 30.0};
  }
  return {1, 0.0, 0.0, 0, 0, 0.0};
}

/// The automatic level with max_error or a size_field: 1 (no refinement). A graded base (sizes k times
/// the output's, the bound k^2 times) refined by k = 4 met fewer of docs/quality.md's --max-error targets
/// than the single level (10 of 18 meshes against 12: on tanglecube and genus2 at about 20k vertices H
/// nRMS rose from 0.0179 and 0.0149 to 0.0198 and 0.0189, and a coarse bound gave 5 times the vertices,
/// the base's partition refining far below its sizes). An explicit level still grades the base.
constexpr int kGradedLevel = 1;
/// The automatic level's floor where the curvature asks for less: at about 20k vertices on the public
/// closed surfaces, level 2 against level 1 gave H nRMS 0.86 to 1.04 times and about 3 times the
/// speed, with smallest angles of 25.7 degrees and more (docs/algorithms.md 8.4). The guard and the angle
/// floor still drop it to 1.
constexpr int kLeastAutomaticLevel = 2;
/// An automatic level whose refined mesh keeps a triangle under this smallest angle (degrees) is halved:
/// the base was too coarse somewhere for its curvature.
constexpr double kAngleFloor = 20.0;

/// With BaseRefinement::keep_base_angles, an automatic level is kept only when its smallest angle is at
/// least the clean-up's floor or no more than kBaseAngleSlack below the base's own (degrees).
constexpr double kCleanupFloor = 25.0;

/// The automatic level at most `ceiling` for a surface of largest curvature `kappa` whose mesh at the
/// target edge length `edge` has about `vertices` vertices: the curvature's level (at least
/// kLeastAutomaticLevel), lowered so that the base keeps the preset's fewest vertices.
int automatic_level(const RefinePreset& preset, double kappa, double edge, double vertices, int ceiling) {
  const int by_curvature = std::max(refine::level_for_curvature(kappa, edge, preset.max_turn, ceiling),
                                    std::min(kLeastAutomaticLevel, ceiling));
  const int by_size = static_cast<int>(
      std::clamp(std::floor(std::sqrt(vertices / preset.min_base)), 1.0, static_cast<double>(ceiling)));
  return std::min(by_curvature, by_size);
}

/// Adds the evaluations and stage times of `from` to `into`.
void add_costs(MeshStats& into, const MeshStats& from) {
  into.value_evaluations += from.value_evaluations;
  into.gradient_evaluations += from.gradient_evaluations;
  into.times.merge(from.times);
}

}  // namespace

bool level_from_curvature(const Settings& settings) {
  return settings.refine == 0 && !settings.max_error && !settings.size_field;
}

Settings base_settings(const Settings& settings, double edge, int level) {
  Settings s = settings;
  s.refine = 1;
  s.edge_length = edge * level;
  if (settings.max_error) s.max_error = *settings.max_error * level * level;  // chordal error ~ h^2
  if (settings.size_field)
    s.size_field = [field = settings.size_field, level](const Vec3& p) { return level * field(p); };
  return s;
}

int first_level(const Settings& settings, double edge, const SizeEstimate* estimate) {
  const bool graded = settings.max_error.has_value() || static_cast<bool>(settings.size_field);
  const RefinePreset preset = refine_preset(settings.quality);
  const int level = settings.refine != 0 ? settings.refine : graded ? kGradedLevel : preset.max_level;
  if (level_from_curvature(settings) && estimate && estimate->found)
    return automatic_level(preset, estimate->largest_curvature, edge, estimate->vertices, level);
  return level;
}

int resolved_level(const Settings& settings, double edge, double largest_curvature, std::size_t base_vertices,
                   int level) {
  if (!level_from_curvature(settings) || level <= 1) return level;
  // About base_vertices * level^2 output vertices.
  const double output_vertices = static_cast<double>(base_vertices) * level * level;
  return automatic_level(refine_preset(settings.quality), largest_curvature, edge, output_vertices, level);
}

refine::RefineParams refine_params(const Settings& settings, const Box& box, int level) {
  const RefinePreset preset = refine_preset(settings.quality);
  refine::RefineParams params;
  params.level = level;
  params.sweeps = preset.sweeps;
  params.angle_sweeps = preset.angle_sweeps;
  params.angle_target = preset.angle_target;
  params.box = box;
  params.region = settings.region;
  params.max_vertices = settings.max_vertices;
  params.cancel = settings.cancel;
  params.progress = settings.progress;
  return params;
}

bool refinement_kept(const Settings& settings, double smallest_angle) {
  return settings.refine != 0 || smallest_angle >= kAngleFloor;
}

bool refinement_kept(const Settings& settings, double smallest_angle, double base_smallest_angle) {
  return refinement_kept(settings, smallest_angle) &&
         (settings.refine != 0 ||
          smallest_angle >= std::min(kCleanupFloor, base_smallest_angle - kBaseAngleSlack));
}

Mesh mesh_multiresolution(const Surface& surface, const Settings& settings, MeshStats* stats,
                          const LevelMesher& mesh_level, const SizeEstimate* estimate,
                          const BaseRefinement& bases) {
  const auto start = std::chrono::steady_clock::now();
  const Box box = settings.box.value_or(surface.box());
  const double edge = default_edge_length(settings, box);
  const bool from_curvature = level_from_curvature(settings);
  int level = first_level(settings, edge, estimate);
  RefineStats info;
  info.target_edge = edge;
  if (from_curvature && estimate && estimate->found) info.estimated_curvature = estimate->largest_curvature;
  info.first_level = level;
  MeshStats spent;       // every attempt's evaluations and times
  MeshStats base_stats;  // the last base's
  Mesh base;
  // A base the partition cannot build at its size (an internal error of the convex overlay, seen with a
  // region plane on a plane of the coarse lattice) is given up like a failed refinement: false.
  const auto mesh_base = [&](int k) {
    base_stats = MeshStats{};
    ++info.attempts;
    try {
      base = mesh_level(base_settings(settings, edge, k), &base_stats);
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::Internal) throw;
      base = Mesh{};
      return false;
    }
    add_costs(spent, base_stats);
    return true;
  };
  // The largest level from `k` down whose base can be built (1 when none).
  const auto usable_level = [&](int k) {
    while (k > 1 && !mesh_base(k)) k /= 2;
    return k;
  };
  const auto finish = [&](Mesh mesh, const MeshStats& last) {
    if (stats) {
      const int threads = stats->threads;  // set by mesh_surface for the whole run
      *stats = last;
      stats->threads = threads;
      stats->value_evaluations = spent.value_evaluations;
      stats->gradient_evaluations = spent.gradient_evaluations;
      stats->times = spent.times;
      stats->vertices = mesh.vertex_count();
      stats->triangles = mesh.triangle_count();
      stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      stats->refine = info;
    }
    return mesh;
  };

  level = usable_level(level);
  if (level > 1) {
    if (from_curvature) {
      info.largest_curvature = bases.largest_curvature ? bases.largest_curvature(base)
                                                       : refine::largest_curvature(base.positions, surface);
      const int resolved = resolved_level(settings, edge, info.largest_curvature, base.vertex_count(), level);
      if (resolved < level) level = usable_level(resolved);
    }
  }
  while (level > 1) {
    const refine::RefineParams params = refine_params(settings, box, level);
    const auto refine_start = std::chrono::steady_clock::now();
    refine::RefineResult refined =
        bases.refine ? bases.refine(base, params) : refine::refine_mesh(base, surface, params);
    spent.gradient_evaluations += refined.gradient_evaluations;
    spent.times.add("refine",
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - refine_start).count());
    const bool kept = refined.failed_points == 0 &&
                      (bases.keep_base_angles ? refinement_kept(settings, refined.smallest_angle,
                                                                refine::smallest_angle_degrees(base))
                                              : refinement_kept(settings, refined.smallest_angle));
    if (kept) {
      info.level = level;
      info.base_vertices = base.vertex_count();
      info.base_triangles = base.triangle_count();
      info.rejected_moves = refined.rejected_moves;
      info.angle_vertices = refined.angle_vertices;
      info.repaired_vertices = refined.repaired_vertices;
      info.smallest_angle = refined.smallest_angle;
      info.gradient_evaluations = refined.gradient_evaluations;
      return finish(std::move(refined.mesh), base_stats);
    }
    info.failed_points += refined.failed_points;
    level = usable_level(level / 2);
  }
  // Level 1: the projection mesher and the clean-up at the target sizes themselves.
  Settings single = settings;
  single.refine = 1;
  MeshStats last;
  Mesh mesh = mesh_level(single, &last);
  add_costs(spent, last);
  ++info.attempts;
  info.level = 1;
  info.base_vertices = mesh.vertex_count();
  info.base_triangles = mesh.triangle_count();
  return finish(std::move(mesh), last);
}

}  // namespace isopatch
