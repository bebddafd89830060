/// \file patch_curvature.cpp
/// A composite base's largest curvature, patch by patch (patch_curvature.hpp).
#include "composite_mesher/patch_curvature.hpp"

#include <algorithm>

#include "refine/refinement_level.hpp"

namespace isopatch {

double largest_patch_curvature(const Composite& composite, const std::vector<std::int32_t>& vertex_patch,
                               const Mesh& base) {
  double largest = 0.0;
  std::vector<std::vector<Vec3>> inside(composite.patches.size());
  for (std::size_t v = 0; v < base.vertex_count(); ++v)
    if (vertex_patch[v] >= 0) inside[static_cast<std::size_t>(vertex_patch[v])].push_back(base.positions[v]);
  for (std::size_t p = 0; p < composite.patches.size(); ++p)
    largest = std::max(largest, refine::largest_curvature(inside[p], *composite.patches[p].surface, true));
  return largest;
}

}  // namespace isopatch
