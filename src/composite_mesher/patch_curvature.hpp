#pragma once
/// \file patch_curvature.hpp
/// The largest curvature a composite's base shows, measured patch by patch: what the automatic level of
/// multiresolution meshing (docs/algorithms.md 8.4) is checked with for a composite.

#include <isopatch/mesh.hpp>

#include <cstdint>
#include <vector>

#include "composite_model/composite.hpp"

namespace isopatch {

/// The largest curvature of `composite` at the vertices of `base` inside patches (vertex_patch[v] >= 0),
/// each on its own patch's function; curve vertices (vertex_patch -1: corners, where I-patch functions
/// are 0/0, and curve samples) are left out, as is a vertex where the curvature is not finite.
/// \pre vertex_patch has one entry per base vertex, each -1 or a patch of `composite`.
/// \throw EvaluationError as refine::largest_curvature().
double largest_patch_curvature(const Composite& composite, const std::vector<std::int32_t>& vertex_patch,
                               const Mesh& base);

}  // namespace isopatch
