#pragma once
/// \file composite_refinement.hpp
/// Multiresolution meshing of a composite surface (docs/algorithms.md 8): its projection mesh at k times
/// the target size (composite_mesher.hpp) refined k times by src/refine. A base edge on a curve takes the
/// curve's own points: the curve sampled at k times its segments (curve_samples.hpp), the points between
/// the edge's two samples, so both patches beside it share them and they lie on the curve exactly as the
/// base's samples do; every other new vertex is put on, and relaxed on, its own patch's function.

#include "composite_mesher/composite_mesher.hpp"
#include "composite_model/composite.hpp"
#include "refine/refine_mesh.hpp"

namespace isopatch {

/// \throw InputError unless `triangle_patch` (one per base triangle, each a patch of `composite`),
///        `curve_segments` (one per curve, 0..kMaxPatchResolution times refine::kMaxLevel) and
///        `curve_vertices` (one list per curve, empty or curve_segments + 1 vertices of `base`) describe a
///        base of `composite`.
void check_composite_parts(const Composite& composite, const Mesh& base,
                           const std::vector<std::uint32_t>& triangle_patch,
                           const std::vector<int>& curve_segments,
                           const std::vector<std::vector<std::uint32_t>>& curve_vertices);

/// `params` as a composite is refined with: the relaxation may not lower a triangle under the angle
/// target further (the curves' held vertices would otherwise close the triangles beside them).
refine::RefineParams composite_refine_params(const refine::RefineParams& params);

/// `base` (mesh_composite_projection(composite, ...)) refined by params.level: every base triangle cut
/// into level^2 triangles of its patch. The result's mesh is empty when the refinement failed its guard
/// (result.failed_points > 0; the caller then uses a smaller level). Otherwise `refined`, when given,
/// receives the refined CompositeMesh (curve_segments and curve_vertices at level times the base's).
/// The same bytes for any thread count.
/// \throw InputError when `base` does not belong to `composite`; otherwise as refine::refine_pieces.
refine::RefineResult refine_composite(const Composite& composite, const CompositeMesh& base,
                                      const refine::RefineParams& params, CompositeMesh* refined = nullptr);

}  // namespace isopatch
