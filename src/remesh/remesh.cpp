// Surface-bound isotropic remeshing (Botsch & Kobbelt 2004), see include/isopatch/remesh.hpp: the
// schedule of the clean-up's passes (cleanup_stages.hpp) over one run's state (remesh_run.hpp).
#include <isopatch/error.hpp>
#include <isopatch/remesh.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "remesh/cleanup_flips.hpp"
#include "remesh/cleanup_stages.hpp"
#include "remesh/defect_region.hpp"
#include "remesh/edge_edits.hpp"
#include "remesh/editable_mesh.hpp"
#include "remesh/error_bound.hpp"
#include "remesh/laplacian_exactness.hpp"
#include "remesh/relaxation.hpp"
#include "remesh/remesh_checks.hpp"
#include "remesh/remesh_run.hpp"
#include "remesh/small_angle_repair.hpp"
#include "surface/sampler.hpp"

namespace isopatch {
namespace {

using namespace cleanup;
using namespace cleanup_stages;

RemeshStats run_local_cleanup(RemeshRun& run);

/// The whole clean-up (cleanup_schedule: setup, settings.iterations rounds, finish); a local run
/// (RemeshSettings::local_only) goes to run_local_cleanup. Returns the run's statistics.
RemeshStats run_cleanup(RemeshRun& run) {
  if (run.settings.local_only) return run_local_cleanup(run);
  run.find_sliding_vertices();
  run.timed(kSizes, [&] { run.sizes.update(run.mesh); });
  const std::size_t steps = static_cast<std::size_t>(run.settings.iterations) + 2;
  for (int it = 0; it < run.settings.iterations; ++it) {
    run.report(static_cast<std::size_t>(it), steps);
    run.timed(kSplit, [&] { split_long_edges(run); });
    run.timed(kSizes, [&] { run.sizes.update(run.mesh); });
    run.timed(kCollapse, [&] {
      collapse_short_edges(run);
      // The collapses' dead slots go before the flips and sweeps walk the slots; a large mesh is
      // also renumbered in space order, as the splits appended their vertices far from their rings.
      run.compact(run.mesh.vertex_slots() >= kSpaceOrderSlots);
    });
    run.timed(kSizes, [&] { run.sizes.update(run.mesh); });
    run.timed(kFlip, [&] { flip_valences(run); });
    run.timed(kRelax, [&] { relax(run); });
    run.timed(kSizes, [&] { run.sizes.update(run.mesh); });
  }
  for (int round = 0; round < 3; ++round) {
    if (run.timed(kRepair, [&] { return repair_small_angles(run); }) == 0) break;
    run.timed(kSizes, [&] { run.sizes.update(run.mesh); });
    run.timed(kFlip, [&] { flip_valences(run); });  // the repairs' collapses leave irregular vertices
    run.timed(kRelax, [&] { relax(run); });
  }
  // Chains that may pass one flip costing energy pull apart the 5-7 pairs neutral chains leave.
  if (run.settings.valence_search > 0)
    run.timed(kValenceSearch,
              [&] { flip_valences(run, GlideLimits{.budget = run.settings.valence_search, .max_debt = 2}); });
  // Connectivity is final: relaxation alone evens out the vertex spacing around the irregular vertices
  // (each flip, split or collapse of a round undoes part of what the relaxation of the round did).
  run.timed(kRelax, [&] { relax(run, run.settings.final_relaxation_rounds); });
  // Splits and collapses left dead slots; the connectivity is final, so the vertices are renumbered along
  // a space-filling curve: each sweep reads the mesh in memory order (half the time on a 1M sphere).
  run.compact(true);
  run.report(steps - 2, steps);
  if (run.settings.curvature_sweeps > 0) {
    const ExactnessMoveRules rules{
        .project = [&run](Vec3& p, Vec3& n, double max_step) { return run.project(p, n, max_step); },
        .triangle_valid = [&run](std::uint32_t t, std::uint32_t v, const Vec3& p,
                                 const Vec3& n) { return run.triangle_ok_with(t, v, p, n); },
        .size = [&run](std::uint32_t v) { return run.sizes.at(v); },
        .angle_floor = kExactnessAngleFloor,
        .before_sweep = [&run] { run.check_cancel(); }};
    run.timed(kCurvature, [&] {
      run.stats.exactness_moves = improve_laplacian_exactness(run.mesh, rules, run.settings.curvature_sweeps);
    });
  }
  run.report(steps - 1, steps);
  run.timed(kRepair, [&] { repair_until_settled(run); });
  if (run.settings.sizes.max_error)
    run.timed(kErrorBound, [&] { run.stats.error_bound_violations = enforce_error_bound(run); });
  run.stats.gradient_evaluations = run.f.gradient_count();
  run.stats.hessian_evaluations = run.sizes.hessian_evaluations();
  return run.stats;
}

/// The preview's local repair: the topological fixes (short edges, small angles, valences) act only
/// where a defect is, then relaxation runs over the vertices near the defects alone (work list), so
/// the cost follows what needs fixing, not the mesh size.
RemeshStats run_local_cleanup(RemeshRun& run) {
  run.find_sliding_vertices();
  run.timed(kSizes, [&] { run.sizes.update(run.mesh); });
  run.timed(kCollapse, [&] { collapse_short_edges(run); });
  run.timed(kRepair, [&] { repair_until_settled(run); });
  run.timed(kFlip, [&] { flip_valences(run, GlideLimits{.budget = kLocalGlideBudget}); });
  // The collapses moved and merged vertices: varying sizes are graded again before the work list.
  run.timed(kSizes, [&] { run.sizes.update(run.mesh); });
  std::vector<std::uint32_t> work;
  run.timed(kRelax, [&] {
    const DefectThresholds thresholds{.cos_small_angle = std::cos(kLocalAngle * std::numbers::pi / 180.0),
                                      .split_factor = kSplitFactor,
                                      .collapse_factor = run.collapse_factor()};
    work = vertices_near_defects(run.mesh, run.sizes, thresholds, kLocalRings);
    relax(run, work, kLocalRelaxationRounds);
  });
  run.timed(kRepair, [&] { repair_until_settled(run); });
  // The relaxation frees flips that its angles refused: one more greedy pass with neutral chains.
  run.timed(kFlip, [&] { flip_valences(run, GlideLimits{.budget = kLocalGlideBudget}); });
  run.timed(kRelax, [&] { relax(run, work, kLocalRelaxationRounds); });
  run.timed(kRepair, [&] { repair_until_settled(run); });
  // Only a mesh still short of the margin above the floor pays for chains that may borrow.
  if (run.settings.valence_search > 0 && valence_six_share(run.mesh) < kLocalValenceShare) {
    run.timed(kValenceSearch, [&] {
      flip_valences(run, GlideLimits{.budget = run.settings.valence_search, .passes = 1, .max_debt = 2});
    });
    run.timed(kRelax, [&] { relax(run, work, 2); });
    run.timed(kRepair, [&] { repair_until_settled(run); });
  }
  run.stats.gradient_evaluations = run.f.gradient_count();
  run.stats.hessian_evaluations = run.sizes.hessian_evaluations();
  return run.stats;
}

}  // namespace

RemeshStats remesh_on_surface(Mesh& mesh, const Surface& surface, const RemeshSettings& settings) {
  check_remesh_settings(settings);
  if (settings.iterations == 0 || mesh.triangles.empty()) return {};
  mesh.validate();
  const Sampler f(surface);
  std::vector<Vec3> normals(mesh.positions.size(), Vec3::Zero());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3 g = f.value_gradient(mesh.positions[v]).gradient;
    if (g.norm() > 0.0) normals[v] = g.normalized();
  }
  const double tolerance = 1e-13 * std::max(bounding_box(mesh).diagonal(), 1e-300);
  EditableMesh editable(mesh, std::move(normals));
  mesh = Mesh{};  // the editable copy is the mesh now: no second copy held through the clean-up
  RemeshRun run(surface, editable, settings, tolerance);
  RemeshStats stats = run_cleanup(run);
  stats.iterations = settings.iterations;
  stats.gradient_evaluations += f.gradient_count();
  mesh = editable.to_mesh();
  return stats;
}

}  // namespace isopatch
