// Valence flips of the surface-bound clean-up, see cleanup_flips.hpp.
#include "remesh/cleanup_flips.hpp"

#include <algorithm>

#include "remesh/valence_flips.hpp"

namespace isopatch::cleanup {

void flip_valences(RemeshRun& run, const GlideLimits& limits) {
  run.check_cancel();
  run.stats.flips += flip_towards_valence_six(
      run.mesh,
      [&run](const EditableMesh::Edge& e, bool neutral) {
        if (neutral) return try_flip(run, e, [&run](double, double after) { return after <= run.cos_glide; });
        return try_flip(run, e, [&run](double before, double after) {
          return after <= std::max(before, run.cos_repair) || after < run.cos_30;
        });
      },
      limits);
}

}  // namespace isopatch::cleanup
