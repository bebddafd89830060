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

/// `base` (mesh_composite_projection(composite, ...)) refined by params.level: every base triangle cut
/// into level^2 triangles of its patch. The result's mesh is empty when the refinement failed its guard
/// (result.failed_points > 0; the caller then uses a smaller level). Otherwise `refined`, when given,
/// receives the refined CompositeMesh (curve_segments and curve_vertices at level times the base's).
/// The same bytes for any thread count.
/// \throw InputError when `base` does not belong to `composite`; otherwise as refine::refine_pieces.
refine::RefineResult refine_composite(const Composite& composite, const CompositeMesh& base,
                                      const refine::RefineParams& params, CompositeMesh* refined = nullptr);

}  // namespace isopatch
