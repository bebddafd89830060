// The surface-bound clean-up (remesh_on_surface) as data: an ordered list of passes over one run's state
// that a caller can read (stage_names), change or extend (insert a pass of its own) and then run
// (remesh_with_plan). remesh_on_surface runs default_cleanup_plan(settings); the run's times
// (RemeshStats::times) are booked under the passes' stage names, so what a plan lists is what ran.
// The schedule follows Botsch & Kobbelt (2004), "A remeshing approach to multiresolution modeling":
// rounds of split, collapse, flip and tangential relaxation, with the repairs and sweeps of
// docs/whole-surface-quality.md after them.
#pragma once

#include <isopatch/mesh.hpp>
#include <isopatch/remesh.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "remesh/cleanup_stages.hpp"
#include "remesh/remesh_run.hpp"

namespace isopatch::cleanup {

/// One pass over the run's state.
struct CleanupPass {
  /// The stage it books its wall time under in RemeshStats::times (the names of cleanup_stages.hpp, or
  /// a caller's own); empty: book-keeping that is not timed (renumbering the slots).
  std::string stage;
  /// What it does to the run. Returns the number of edits it made where it counts them (a repeated
  /// step stops once its first pass makes none), else 0. May throw what the run throws (LimitError on
  /// cancel).
  std::function<std::size_t(RemeshRun&)> apply;
};

/// Passes taken together: run in order, `repeats` times at most.
struct CleanupStep {
  std::vector<CleanupPass> passes;
  /// How many times the passes run (>= 1). With more than one, the step ends as soon as its first pass
  /// makes no edit (the rest of that repeat is skipped).
  int repeats = 1;
  /// Empty: the step always runs. Else it runs only when this holds for the run as it is then.
  std::function<bool(const RemeshRun&)> when;
  /// Whether settings.progress hears of the run's progress just before this step (one of the finishing
  /// steps that the progress counts after the rounds).
  bool reports_progress = false;
};

/// The clean-up: `setup` once, `round` CleanupEffort::iterations times (progress reported at the
/// start of each), then `finish` once.
struct CleanupPlan {
  std::vector<CleanupStep> setup;
  std::vector<CleanupStep> round;
  std::vector<CleanupStep> finish;
};

/// A step of one pass.
CleanupStep single_pass(std::string stage, std::function<std::size_t(RemeshRun&)> apply);

/// The stage names of `steps`' passes in the order they run once each (a repeated step's passes once;
/// untimed passes left out).
std::vector<std::string_view> stage_names(const std::vector<CleanupStep>& steps);

/// The plan remesh_on_surface follows for `settings` (valid, check_remesh_settings), with the effort
/// its clean-up settings ask for (cleanup_effort, remesh_presets.hpp):
///   the whole clean-up: setup {sizes}; round {split, sizes, collapse, sizes, flip, relax, sizes};
///     finish {repairs with their flips and relaxation until a repair changes nothing (three times at
///     most), the valence search (valence_search > 0), the final relaxation, the curvature sweeps
///     (curvature_sweeps > 0), a last repair, the error bound (sizes.max_error)};
///   a local run (the preview preset, local_only): no rounds; finish {collapse, repair, flip, sizes,
///   relaxation near the
///     defects, repair, flip, relaxation, repair, and while the valence-six share is below its margin
///     the valence search with a relaxation and a repair}.
/// Deterministic: a function of the settings alone.
CleanupPlan default_cleanup_plan(const RemeshSettings& settings);

/// remesh_on_surface with `plan` instead of the default one (the same checks, set-up, projection and
/// output; the same guarantees hold for the default passes, and a caller's pass must keep them: every
/// vertex on f = 0, triangles valid as RemeshRun::triangle_ok). Adds each pass's wall time under its
/// stage. \throw as remesh_on_surface, and what a caller's pass throws.
RemeshStats remesh_with_plan(Mesh& mesh, const Surface& surface, const RemeshSettings& settings,
                             const CleanupPlan& plan);

}  // namespace isopatch::cleanup
