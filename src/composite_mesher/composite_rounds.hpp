#pragma once
/// \file composite_rounds.hpp
/// The composite as a producer of patch jobs for the projection core: every patch projected
/// (composite_patch.hpp) in parallel, rejected patches' curves refined by the one refinement loop
/// (projection/refinement_rounds.hpp: Sipos & Salvi 2021, sec. 2.3), the patches still rejected at the
/// end closed by fans.

#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>

#include <memory>
#include <vector>

#include "composite_mesher/composite_curves.hpp"
#include "composite_mesher/composite_patch.hpp"
#include "composite_model/composite.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

/// The patches as projected: the curves' last sampling, each patch's piece, which are fans.
struct ProjectedPatches {
  CurveSampling sampling;
  std::vector<PatchPiece> pieces;  ///< per patch
  std::vector<bool> fan;           ///< per patch: closed by a fan
};

/// Projects every patch of `c` with `params`, doubling the segments of the curves of rejected patches
/// (in `curves`, at most kMaxPatchResolution) for at most settings.refinement_levels rounds; reports
/// progress and checks cancellation (settings); counts rejections and rounds in `ps`.
/// `samplers[p]` evaluates patch p's function; patches run in parallel (TBB, the caller's arena), with
/// the same result for any number of threads.
/// \throw InputError for a malformed patch; EvaluationError; LimitError when cancelled.
ProjectedPatches project_patches(const Composite& c, const std::vector<std::unique_ptr<Sampler>>& samplers,
                                 CurvePlan& curves, const CompositePatchParams& params,
                                 const Settings& settings, ProjectionStats& ps);

}  // namespace isopatch
