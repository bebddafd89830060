#pragma once
/// \file cell_checks.hpp
/// The per-cell work shared by the uniform and the adaptive partition builders: the sampled
/// single-sheet tests of docs/algorithms.md 2.9 (in-face gradients, normal cone), the orientation check
/// of 2.9.4, and the crossing of f = 0 on one lattice segment (2.7).

#include <cstdint>
#include <vector>

#include "partition/cell.hpp"
#include "partition/partition.hpp"
#include "partition/sample_cache.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

/// Face test (docs/algorithms.md 2.9.2) on face f of `cell`: the in-plane gradients at its 4 corners and its
/// centre pairwise agree.
bool face_gradients_agree(SampleCache& cache, const Cell& cell, int face);

/// Normal-cone test (docs/algorithms.md 2.9.3): gradients at the corners, the centre, the face centres
/// and the loops' corners lie within the cone of half-angle acos(cos_cone) about their mean direction.
bool cell_gradients_within_cone(SampleCache& cache, const Cell& cell, const std::vector<Loop>& loops,
                                const std::vector<Crossing>& crossings, double cos_cone);

/// The orientation check of docs/algorithms.md 2.9.4: the loop's Newell normal agrees with the mean unit
/// gradient at its corners (loops are oriented by the signs already; this asks whether the geometry agrees).
bool loop_oriented_along_gradient(const Loop& loop, const std::vector<Crossing>& crossings);

/// Root finding on a lattice segment, shared by both builders: tolerance on the edge parameter t in
/// [0, 1], and the iteration cap.
inline constexpr double kSegmentRootTolerance = 1e-13;
inline constexpr int kSegmentRootIterations = 100;

/// The crossing on segment `key` (docs/algorithms.md 2.7), from its negative end A: phi(t) = f(A + t (B - A))
/// on [0, 1] by the shared bracketed root finder to `tolerance` in t. `fa`, `fb`: f at key.start and
/// key.end() (opposite signs). Root evaluations are added to `root_evaluations`.
/// \throw EvaluationError when f or its gradient is not finite.
Crossing segment_crossing(const Sampler& sampler, const Lattice& lattice, const SegmentKey& key, double fa,
                          double fb, double tolerance, int max_iterations, std::uint64_t& root_evaluations);

}  // namespace isopatch
