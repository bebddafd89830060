#pragma once
/// \file fairing.hpp
/// Laplace fairing with re-projection, the post-processing baseline of the paper's Figure 2 (Sipos &
/// Salvi 2021, sec. 1): each iteration moves every vertex to the centroid of its neighbours and then
/// back onto f = 0 by Newton steps along grad f. Connectivity is unchanged, so the valences of the
/// input (e.g. Marching Cubes) remain.

#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <cstdint>

namespace isopatch {

struct FairingStats {
  std::uint64_t gradient_evaluations = 0;  ///< evaluations of f with its gradient (the projections)
  std::size_t unconverged = 0;  ///< vertex projections that did not reach f = 0 in the last round (those
                                ///< vertices kept their position)
};

/// Applies `iterations` rounds of umbrella smoothing + projection to the vertices of `mesh` that are
/// not on a boundary edge (boundary vertices stay, so a mesh clipped by its box keeps its rim).
/// \throw InputError if iterations < 0 or > 10000; EvaluationError if f or grad f is NaN/inf.
FairingStats laplace_fair(Mesh& mesh, const Surface& surface, int iterations);

}  // namespace isopatch
