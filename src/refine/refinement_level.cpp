// The refinement level from curvature (refinement_level.hpp).
#include "refine/refinement_level.hpp"

#include <isopatch/error.hpp>
#include <isopatch/level_set_curvature.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>

namespace isopatch::refine {

double largest_curvature(std::span<const Vec3> points, const Surface& surface, bool skip_undefined) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, points.size(), 1024), 0.0,
      [&](const tbb::blocked_range<std::size_t>& r, double largest) {
        for (std::size_t v = r.begin(); v != r.end(); ++v) {
          const double kappa = max_abs_principal_curvature(surface, points[v]);
          if (skip_undefined && !std::isfinite(kappa)) continue;
          if (std::isnan(kappa))
            throw EvaluationError("the curvature of f = 0 is not finite at a base vertex");
          largest = std::max(largest, kappa);
        }
        return largest;
      },
      [](double a, double b) { return std::max(a, b); });
}

int level_for_curvature(double kappa, double edge, double max_turn, int max_level) {
  if (!(kappa > 0.0)) return max_level;
  const double k = std::floor(max_turn / (edge * kappa));
  return static_cast<int>(std::clamp(k, 1.0, static_cast<double>(max_level)));
}

}  // namespace isopatch::refine
