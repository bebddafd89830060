#pragma once
// Edge flips that bring vertex valences towards 6 (4 on a locked boundary vertex): greedy flips that
// lower the valence energy sum (valence - target)^2, then "glide" chains, sequences of energy-neutral
// flips that walk an irregular vertex pair (a 5-7 dislocation) across the mesh until a flip that
// lowers the energy appears, where the pair meets another irregular vertex and both disappear
// (Surazhsky & Gotsman, "Explicit surface remeshing", SGP 2003, section 5, move irregular vertices by
// flips until they cancel). A chain may also be allowed to borrow: pass through one flip that costs
// energy (it makes a new pair) as long as it ends below where it started. Chains that find nothing
// are undone, so the energy never rises.

#include <cstddef>
#include <functional>

#include "remesh/editable_mesh.hpp"

namespace isopatch {

/// The valence a vertex should have: 4 on a locked (boundary) vertex, 6 inside.
inline int target_valence(const EditableMesh& mesh, std::uint32_t v) {
  return mesh.locked[v] ? 4 : 6;
}

/// Share of the free (alive, unlocked) vertices whose valence is 6; 1 when there is none.
double valence_six_share(const EditableMesh& mesh);

/// Change of the valence energy over the four vertices of e when e is flipped (negative: better).
int flip_energy_change(const EditableMesh& mesh, const EditableMesh::Edge& e);

/// Performs the flip of e when the geometry allows it and returns whether it did. `neutral` is true
/// for the energy-neutral flips of a glide chain, which may accept worse angles (relaxation follows).
using FlipIfValid = std::function<bool(const EditableMesh::Edge& e, bool neutral)>;

struct GlideLimits {
  int depth = 16;    ///< flips per chain before it is abandoned
  int budget = 200;  ///< flips tried per chain, over all branches
  int passes = 1;    ///< sweeps of glide chains; stops early when a sweep changes nothing
  /// Energy a chain may borrow on its way: 0, neutral flips only; 2, one flip that makes a new
  /// irregular pair is allowed, so that pairs stuck side by side can be pulled apart and cancelled.
  int max_debt = 0;
};

/// One sweep of greedy flips, then glide chains from the edges near irregular vertices (at most
/// limits.passes sweeps; the remesher calls this once per round, between relaxations).
/// Returns the flips kept. \post the valence energy did not rise.
std::size_t flip_towards_valence_six(EditableMesh& mesh, const FlipIfValid& flip,
                                     const GlideLimits& limits = {});

}  // namespace isopatch
