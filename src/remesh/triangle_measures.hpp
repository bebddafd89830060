#pragma once
// Two measures of one triangle of an editable mesh that the enforcement of a chordal error bound uses
// (docs/algorithms.md 5.8): its centroid's first-order distance from f = 0 and its longest edge.

#include <isopatch/geometry.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "surface/sampler.hpp"

namespace isopatch {

/// |f| / |grad f| at the centroid of triangle t (what `analyze` reports as the centroid distance);
/// infinity where grad f vanishes or f is not finite. Never throws.
inline double centroid_distance(const Sampler& f, const std::vector<Vec3>& positions, const Triangle& t) {
  const Vec3 c = (positions[t[0]] + positions[t[1]] + positions[t[2]]) / 3.0;
  const auto vg = f.value_gradient_unchecked(c);
  const double g = vg.gradient.norm();
  return g > 0.0 && std::isfinite(vg.value) ? std::abs(vg.value) / g
                                            : std::numeric_limits<double>::infinity();
}

/// The longest edge of triangle t (the first of equal ones), its lower vertex first.
inline std::pair<std::uint32_t, std::uint32_t> longest_edge(const std::vector<Vec3>& positions,
                                                            const Triangle& t) {
  const auto length = [&](std::uint32_t a, std::uint32_t b) { return (positions[a] - positions[b]).norm(); };
  std::pair<std::uint32_t, std::uint32_t> longest{t[0], t[1]};
  for (std::size_t i = 1; i < 3; ++i)
    if (length(t[i], t[(i + 1) % 3]) > length(longest.first, longest.second))
      longest = {t[i], t[(i + 1) % 3]};
  if (longest.first > longest.second) std::swap(longest.first, longest.second);
  return longest;
}

}  // namespace isopatch
