#pragma once
// Colour maps of the renderer's field modes, and the robust default range.

#include <isopatch/render.hpp>

#include <vector>

namespace isopatch::render {

/// Diverging map: t = -1 blue, 0 white, +1 red, linear between five fixed stops; saturates beyond
/// [-1, 1]. \pre t is finite.
Colour diverging_colour(double t);

/// Sequential map: t = 0 light yellow through orange to t = 1 dark red; saturates outside [0, 1].
/// \pre t is finite.
Colour sequential_colour(double t);

/// The nearest-rank `percentile`-th percentile (in (0, 100]) of |v| over the finite values; 0 when
/// there is no finite value.
double robust_magnitude(const std::vector<double>& values, double percentile);

}  // namespace isopatch::render
