// The clean-up settings of the quality presets (remesh_presets.hpp).
#include "remesh/remesh_presets.hpp"

#include <algorithm>

namespace isopatch {

RemeshSettings preset_remesh_settings(const Settings& s, int iterations) {
  RemeshSettings r;
  r.iterations = iterations;
  r.valence_search = s.valence_search;
  r.curvature_sweeps = s.curvature_sweeps;
  switch (s.quality) {
    case Quality::Preview:
      r.local_only = true;
      break;
    case Quality::Default:
      break;
    case Quality::Fine:
      // More of what lowers the curvature error (docs/performance.md).
      r.curvature_sweeps = std::min(kMaxCurvatureSweeps, 2 * s.curvature_sweeps);
      r.final_relaxation_rounds = 12;
      r.valence_search = std::min(kMaxValenceSearch, 2 * s.valence_search);
      break;
  }
  r.cancel = s.cancel;
  r.progress = s.progress;
  return r;
}

}  // namespace isopatch
