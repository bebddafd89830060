/// \file composite_rounds.cpp
/// The composite's patches through the refinement loop (composite_rounds.hpp).
#include "composite_mesher/composite_rounds.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "projection/refinement_rounds.hpp"

namespace isopatch {

ProjectedPatches project_patches(const Composite& c, const std::vector<std::unique_ptr<Sampler>>& samplers,
                                 CurvePlan& curves, const CompositePatchParams& params,
                                 const Settings& settings, ProjectionStats& ps) {
  std::vector<int>& segments = curves.segments;
  ProjectedPatches out;
  std::vector<PatchPiece>& pieces = out.pieces;
  CurveSampling& sampling = out.sampling;
  std::vector<bool>& fan = out.fan;
  const std::size_t patches = c.patches.size();
  pieces.resize(patches);
  fan.assign(patches, false);
  std::size_t passes = 0;
  // The rejected patches of the last pass closed by fans over their boundaries, as sampled.
  const auto close = [&](const std::vector<std::size_t>& rejected) {
    for (const std::size_t p : rejected) {
      fan[p] = true;
      pieces[p] = fan_patch(*samplers[p], c.patches[p], boundary_of(c.patches[p], sampling, curves), params);
    }
  };
  // One pass: every patch projected in parallel (close_rejected: the rejected ones fanned instead).
  const auto pass = [&](bool close_rejected) {
    sampling = sample_curves(c, curves);
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, patches), [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t p = r.begin(); p != r.end(); ++p)
            pieces[p] = project_composite_patch(*samplers[p], c.patches[p],
                                                boundary_of(c.patches[p], sampling, curves), params);
        });
    std::vector<std::size_t> rejected;
    for (std::size_t p = 0; p < patches; ++p)
      if (pieces[p].verdict != PatchVerdict::Accepted) rejected.push_back(p);
    ps.rejected_patches += rejected.size();
    if (settings.progress)
      settings.progress({++passes, static_cast<std::size_t>(settings.refinement_levels + 1)});
    if (close_rejected) {
      close(rejected);
      rejected.clear();
    }
    return rejected;
  };
  // Refinement: the curves of every rejected patch get twice their segments (up to the most a side takes).
  const auto refine = [&](const std::vector<std::size_t>& rejected) {
    bool refined = false;
    for (const std::size_t p : rejected)
      for (const PatchSide& s : c.patches[p].sides)
        if (segments[s.curve] < kMaxPatchResolution) {
          segments[s.curve] = std::min(kMaxPatchResolution, 2 * segments[s.curve]);
          refined = true;
        }
    return refined;
  };
  ps.refinements = refine_until_accepted(settings.refinement_levels, pass, refine, close,
                                         [&] { settings.check_cancel(); });

  return out;
}

}  // namespace isopatch
