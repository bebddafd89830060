// Edge flips of the surface-bound clean-up (one run's state: remesh_run.hpp).
#pragma once

#include <algorithm>

#include "remesh/editable_mesh.hpp"
#include "remesh/remesh_run.hpp"
#include "remesh/valence_flips.hpp"

namespace isopatch::cleanup {

/// Flips e when its two new triangles are valid and `accept` agrees, given the cosines of the
/// smallest angles of the old and of the new pair (a larger cosine is a smaller angle; cosines
/// rather than angles: this is the inner loop of the flips).
template <class Accept>
bool try_flip(RemeshRun& run, const EditableMesh::Edge& e, Accept accept) {
  if (run.mesh.valence(e.a) <= run.fewest(e.a) || run.mesh.valence(e.b) <= run.fewest(e.b)) return false;
  if (run.mesh.adjacent(e.c, e.d)) return false;
  const Triangle t1{e.a, e.d, e.c}, t2{e.b, e.c, e.d};
  if (!run.triangle_ok(t1) || !run.triangle_ok(t2)) return false;
  const double before = std::max(run.smallest_angle_cosine(run.mesh.triangles[e.t_ab]),
                                 run.smallest_angle_cosine(run.mesh.triangles[e.t_ba]));
  const double after = std::max(run.smallest_angle_cosine(t1), run.smallest_angle_cosine(t2));
  if (!accept(before, after)) return false;
  run.mesh.flip(e);
  return true;
}

/// Valence flips (valence_flips.hpp). A flip that lowers the valence energy may not lower the
/// pair's smallest angle below min(old, 20 degrees) unless it stays above 30; a neutral flip of a
/// glide chain only has to stay above kGlideAngle, the relaxation that follows evens it out.
void flip_valences(RemeshRun& run, const GlideLimits& limits = {});

}  // namespace isopatch::cleanup
