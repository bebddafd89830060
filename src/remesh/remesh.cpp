// Surface-bound isotropic remeshing (Botsch & Kobbelt 2004), see include/isopatch/remesh.hpp: a plan of
// passes (cleanup_plan.hpp) run over one run's state (remesh_run.hpp).
#include <isopatch/error.hpp>
#include <isopatch/remesh.hpp>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "remesh/cleanup_plan.hpp"
#include "remesh/editable_mesh.hpp"
#include "remesh/remesh_checks.hpp"
#include "remesh/remesh_presets.hpp"
#include "remesh/remesh_run.hpp"
#include "surface/sampler.hpp"

namespace isopatch {
namespace cleanup {
namespace {

/// Runs one pass, its wall time booked under its stage when it has one; returns its edits.
std::size_t run_pass(RemeshRun& run, const CleanupPass& pass) {
  if (pass.stage.empty()) return pass.apply(run);
  return run.timed(pass.stage.c_str(), [&] { return pass.apply(run); });
}

/// Runs one step (cleanup_plan.hpp: its condition, its repeats, ending once its first pass edits nothing).
void run_step(RemeshRun& run, const CleanupStep& step) {
  if (step.when && !step.when(run)) return;
  for (int repeat = 0; repeat < std::max(step.repeats, 1); ++repeat)
    for (std::size_t k = 0; k < step.passes.size(); ++k)
      if (run_pass(run, step.passes[k]) == 0 && k == 0 && step.repeats > 1) return;
}

/// The whole plan: setup, the rounds (progress reported at the start of each), then the finishing steps
/// (progress reported before those that ask). Returns the run's statistics.
RemeshStats run_plan(RemeshRun& run, const CleanupPlan& plan) {
  const std::size_t rounds = plan.round.empty() ? 0 : static_cast<std::size_t>(run.effort.iterations);
  const std::size_t steps = rounds + static_cast<std::size_t>(std::count_if(
                                         plan.finish.begin(), plan.finish.end(),
                                         [](const CleanupStep& s) { return s.reports_progress; }));
  for (const CleanupStep& s : plan.setup) run_step(run, s);
  for (std::size_t it = 0; it < rounds; ++it) {
    run.report(it, steps);
    for (const CleanupStep& s : plan.round) run_step(run, s);
  }
  std::size_t reported = rounds;
  for (const CleanupStep& s : plan.finish) {
    if (s.reports_progress) run.report(reported++, steps);
    run_step(run, s);
  }
  run.stats.gradient_evaluations = run.f.gradient_count();
  run.stats.hessian_evaluations = run.sizes.hessian_evaluations();
  return run.stats;
}

}  // namespace

RemeshStats remesh_with_plan(Mesh& mesh, const Surface& surface, const RemeshSettings& settings,
                             const CleanupPlan& plan) {
  check_remesh_settings(settings);
  if (cleanup_effort(settings.cleanup).iterations == 0 || mesh.triangles.empty()) return {};
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
  RemeshStats stats = run_plan(run, plan);
  stats.iterations = run.effort.iterations;
  stats.gradient_evaluations += f.gradient_count();
  mesh = editable.to_mesh();
  return stats;
}

}  // namespace cleanup

RemeshStats remesh_on_surface(Mesh& mesh, const Surface& surface, const RemeshSettings& settings) {
  check_remesh_settings(settings);
  return cleanup::remesh_with_plan(mesh, surface, settings, cleanup::default_cleanup_plan(settings));
}

}  // namespace isopatch
