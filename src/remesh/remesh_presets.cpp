// The clean-up settings of the quality presets (remesh_presets.hpp).
#include "remesh/remesh_presets.hpp"

#include <algorithm>

namespace isopatch {
namespace {

/// Relaxation-only rounds once connectivity is final: 8 lower the mean-curvature error by 10-45% for
/// about a fifth more time (docs/whole-surface-quality.md); the fine preset takes 12.
constexpr int kFinalRelaxationRounds = 8;
constexpr int kFineFinalRelaxationRounds = 12;

}  // namespace

CleanupEffort cleanup_effort(const CleanupSettings& c) {
  CleanupEffort e;
  e.iterations = c.remesh_iterations.value_or(kDefaultRemeshIterations);
  e.valence_search = c.valence_search;
  e.curvature_sweeps = c.curvature_sweeps;
  e.final_relaxation_rounds = kFinalRelaxationRounds;
  switch (c.quality) {
    case Quality::Preview:
      e.local_only = true;
      break;
    case Quality::Default:
      break;
    case Quality::Fine:
      // More of what lowers the curvature error (docs/performance.md).
      e.curvature_sweeps = std::min(kMaxCurvatureSweeps, 2 * c.curvature_sweeps);
      e.final_relaxation_rounds = kFineFinalRelaxationRounds;
      e.valence_search = std::min(kMaxValenceSearch, 2 * c.valence_search);
      break;
  }
  return e;
}

RemeshSettings preset_remesh_settings(const Settings& s, int iterations) {
  RemeshSettings r;
  r.cleanup = static_cast<const CleanupSettings&>(s);
  r.cleanup.remesh_iterations = iterations;
  r.cancel = s.cancel;
  r.progress = s.progress;
  return r;
}

}  // namespace isopatch
