// The clean-up's default plan (cleanup_plan.hpp): which passes, in which order, for some settings.
#include "remesh/cleanup_plan.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

#include "remesh/cleanup_flips.hpp"
#include "remesh/cut_edge_splits.hpp"
#include "remesh/defect_region.hpp"
#include "remesh/edge_edits.hpp"
#include "remesh/error_bound.hpp"
#include "remesh/laplacian_exactness.hpp"
#include "remesh/relaxation.hpp"
#include "remesh/small_angle_repair.hpp"

namespace isopatch::cleanup {
namespace {

using namespace cleanup_stages;

/// A pass that edits without counting its edits.
template <class Edit>
CleanupPass uncounted(std::string stage, Edit edit) {
  return {std::move(stage), [edit](RemeshRun& run) -> std::size_t {
            edit(run);
            return 0;
          }};
}

CleanupPass update_sizes() {
  return uncounted(kSizes, [](RemeshRun& run) { run.sizes.update(run.mesh); });
}
CleanupPass flips(GlideLimits limits = {}) {
  return uncounted(kFlip, [limits](RemeshRun& run) { flip_valences(run, limits); });
}
CleanupPass relaxation(int rounds) {
  return uncounted(kRelax, [rounds](RemeshRun& run) { relax(run, rounds); });
}
CleanupPass relaxation_near_defects(int rounds) {
  return uncounted(kRelax, [rounds](RemeshRun& run) { relax(run, run.near_defects, rounds); });
}
CleanupPass repair_to_the_end() {
  return uncounted(kRepair, [](RemeshRun& run) { repair_until_settled(run); });
}
CleanupPass valence_search(GlideLimits limits) {
  return uncounted(kValenceSearch, [limits](RemeshRun& run) { flip_valences(run, limits); });
}
CleanupStep step(CleanupPass pass) {
  return CleanupStep{{std::move(pass)}, 1, {}, false};
}

/// Sets up what every pass reads: the vertices that slide on the box or the region's planes (untimed).
CleanupStep find_sliding() {
  return step(uncounted("", [](RemeshRun& run) { run.find_sliding_vertices(); }));
}

/// The preview's local repair: the topological fixes (short edges, small angles, valences) act only
/// where a defect is, then relaxation runs over the vertices near the defects alone, so the cost
/// follows what needs fixing, not the mesh size.
CleanupPlan local_plan(const CleanupEffort& effort) {
  CleanupPlan plan;
  plan.setup = {find_sliding(), step(update_sizes())};
  const GlideLimits greedy{.budget = kLocalGlideBudget};
  plan.finish = {
      step(uncounted(kCollapse, [](RemeshRun& run) { collapse_short_edges(run); })),
      step(repair_to_the_end()),
      step(flips(greedy)),
      // The collapses moved and merged vertices: varying sizes are graded again before the work list.
      step(update_sizes()),
      step(uncounted(kRelax,
                     [](RemeshRun& run) {
                       const DefectThresholds thresholds{
                           .cos_small_angle = std::cos(kLocalAngle * std::numbers::pi / 180.0),
                           .split_factor = kSplitFactor,
                           .collapse_factor = run.collapse_factor()};
                       run.near_defects = vertices_near_defects(run.mesh, run.sizes, thresholds, kLocalRings);
                       relax(run, run.near_defects, kLocalRelaxationRounds);
                     })),
      step(repair_to_the_end()),
      // The relaxation frees flips that its angles refused: one more greedy pass with neutral chains.
      step(flips(greedy)),
      step(relaxation_near_defects(kLocalRelaxationRounds)),
      step(repair_to_the_end()),
  };
  // Only a mesh still short of the margin above the floor pays for chains that may borrow.
  if (effort.valence_search > 0)
    plan.finish.push_back(
        {{valence_search(GlideLimits{.budget = effort.valence_search, .passes = 1, .max_debt = 2}),
          relaxation_near_defects(2), repair_to_the_end()},
         1,
         [](const RemeshRun& run) { return valence_six_share(run.mesh) < kLocalValenceShare; },
         false});
  return plan;
}

}  // namespace

CleanupStep single_pass(std::string stage, std::function<std::size_t(RemeshRun&)> apply) {
  return step(CleanupPass{std::move(stage), std::move(apply)});
}

std::vector<std::string_view> stage_names(const std::vector<CleanupStep>& steps) {
  std::vector<std::string_view> names;
  for (const CleanupStep& s : steps)
    for (const CleanupPass& p : s.passes)
      if (!p.stage.empty()) names.push_back(p.stage);
  return names;
}

CleanupPlan default_cleanup_plan(const RemeshSettings& settings) {
  const CleanupEffort effort = cleanup_effort(settings.cleanup);
  if (effort.local_only) return local_plan(effort);
  CleanupPlan plan;
  plan.setup = {find_sliding(), step(update_sizes())};
  plan.round = {
      step(uncounted(kSplit,
                     [](RemeshRun& run) {
                       split_long_edges(run);
                       split_long_cut_edges(run);
                     })),
      step(update_sizes()),
      step(uncounted(kCollapse,
                     [](RemeshRun& run) {
                       collapse_short_edges(run);
                       // The collapses' dead slots go before the flips and sweeps walk the slots; a large
                       // mesh is also renumbered in space order, as the splits appended their vertices far
                       // from their rings.
                       run.compact(run.mesh.vertex_slots() >= kSpaceOrderSlots);
                     })),
      step(update_sizes()),
      step(flips()),
      step(relaxation(1)),
      step(update_sizes()),
  };
  // Repairs until one changes nothing (three at most); their collapses leave irregular vertices.
  plan.finish.push_back({{{kRepair, [](RemeshRun& run) { return repair_small_angles(run); }},
                          update_sizes(),
                          flips(),
                          relaxation(1)},
                         3,
                         {},
                         false});
  // Chains that may pass one flip costing energy pull apart the 5-7 pairs neutral chains leave.
  if (effort.valence_search > 0)
    plan.finish.push_back(step(valence_search(GlideLimits{.budget = effort.valence_search, .max_debt = 2})));
  // Connectivity is final: relaxation alone evens out the vertex spacing around the irregular vertices
  // (each flip, split or collapse of a round undoes part of what the relaxation of the round did).
  plan.finish.push_back(step(relaxation(effort.final_relaxation_rounds)));
  // Splits and collapses left dead slots; the connectivity is final, so the vertices are renumbered along
  // a space-filling curve: each sweep reads the mesh in memory order (half the time on a 1M sphere).
  CleanupStep renumber = step(uncounted("", [](RemeshRun& run) { run.compact(true); }));
  renumber.reports_progress = true;
  plan.finish.push_back(std::move(renumber));
  if (effort.curvature_sweeps > 0)
    plan.finish.push_back(step(uncounted(kCurvature, [](RemeshRun& run) {
      const ExactnessMoveRules rules{
          .project = [&run](Vec3& p, Vec3& n, double max_step) { return run.project(p, n, max_step); },
          .triangle_valid = [&run](std::uint32_t t, std::uint32_t v, const Vec3& p,
                                   const Vec3& n) { return run.triangle_ok_with(t, v, p, n); },
          .size = [&run](std::uint32_t v) { return run.sizes.at(v); },
          .angle_floor = kExactnessAngleFloor,
          .before_sweep = [&run] { run.check_cancel(); }};
      run.stats.exactness_moves = improve_laplacian_exactness(run.mesh, rules, run.effort.curvature_sweeps);
    })));
  CleanupStep last_repair = step(repair_to_the_end());
  last_repair.reports_progress = true;
  plan.finish.push_back(std::move(last_repair));
  if (settings.sizes.max_error)
    plan.finish.push_back(step(uncounted(
        kErrorBound, [](RemeshRun& run) { run.stats.error_bound_violations = enforce_error_bound(run); })));
  return plan;
}

}  // namespace isopatch::cleanup
