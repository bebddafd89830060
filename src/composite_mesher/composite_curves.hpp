#pragma once
/// \file composite_curves.hpp
/// The curves of a composite as the mesher shares them (Sipos & Salvi 2021, sec. 2 and 4: boundary
/// vertices computed once and referenced by both patches, so the mesh is watertight without welding):
/// how many segments each curve gets, its samples with mesh ids, the dense polylines the Coons base is
/// built over, and the boundary of one patch read from them.

#include <isopatch/geometry.hpp>
#include <isopatch/stage_settings.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "composite_mesher/composite_patch.hpp"
#include "composite_model/composite.hpp"

namespace isopatch {

/// The curves' segment counts and dense polylines for one mesh.
struct CurvePlan {
  std::vector<int> segments;             ///< per curve; 1 for a curve no patch uses
  std::vector<bool> used;                ///< per curve: whether a patch side runs along it
  std::vector<std::vector<Vec3>> dense;  ///< per used curve, its dense polyline (Coons base)
};

/// Every used curve gets the most segments that either patch using it asks for: its length over the
/// target size on that patch's function (read at a few points when sizes vary; rounded, 1..
/// kMaxPatchResolution), or `resolution` when > 0.
/// \throw InputError for an arc that is not finite or has no length (curve_samples.hpp);
///        EvaluationError from the target sizes.
CurvePlan plan_curves(const Composite& c, const TargetSizes& sizes, int resolution);

/// The curves sampled at their segment counts, with mesh ids: the corners first (in the order the
/// curves meet them), then each curve's inner samples in curve order.
struct CurveSampling {
  std::vector<Vec3> positions;
  std::size_t corners = 0;                      ///< positions[0, corners) are the corners
  std::vector<std::vector<std::uint32_t>> ids;  ///< per curve, start to end
  std::vector<std::vector<Vec3>> points;        ///< per curve, start to end
};

/// Samples every used curve of `plan` (curves no patch uses get no vertices); corners shared by
/// position. \throw InputError as plan_curves().
CurveSampling sample_curves(const Composite& c, const CurvePlan& plan);

/// The boundary of one patch: its sides' samples, ids and dense polylines in the sides' directions.
PatchBoundary boundary_of(const CompositePatch& patch, const CurveSampling& s, const CurvePlan& plan);

}  // namespace isopatch
