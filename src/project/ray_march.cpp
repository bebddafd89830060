#include "project/ray_march.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "surface/bracketed_root.hpp"

namespace isopatch {

double exit_distance(const Vec3& p, const Vec3& d, const Box& box) {
  double t = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (d[a] > 0.0)
      t = std::min(t, (box.hi[a] - p[a]) / d[a]);
    else if (d[a] < 0.0)
      t = std::min(t, (box.lo[a] - p[a]) / d[a]);
  }
  return std::max(t, 0.0);
}

std::optional<RayHit> march_to_surface(const Sampler& f, const Vec3& start, double f_start,
                                       const Vec3& direction, const Box& region,
                                       const RayMarchSettings& settings) {
  const double norm = direction.norm();
  if (!(norm > 0.0)) return std::nullopt;
  // The direction points to the positive side: from a negative start go along it, else against it.
  const Vec3 d = (f_start < 0.0 ? 1.0 : -1.0) * direction / norm;
  if (f_start == 0.0) return RayHit{start, d, 0.0};
  const double diagonal = region.diagonal();
  const Box grown{region.lo - Vec3::Constant(settings.exit_margin * diagonal),
                  region.hi + Vec3::Constant(settings.exit_margin * diagonal)};
  const double t_max = exit_distance(start, d, grown);
  if (!(t_max > 0.0)) return std::nullopt;
  const double step = t_max / settings.steps;
  const bool start_positive = f_start >= 0.0;
  double t_a = 0.0, f_a = f_start;
  for (int i = 1; i <= settings.steps; ++i) {
    const double t_b = i == settings.steps ? t_max : i * step;
    const double f_b = f.value(start + t_b * d);
    if ((f_b >= 0.0) != start_positive) {
      const auto phi = [&](double t) { return f.value(start + t * d); };
      const double t = bracketed_root(phi, t_a, f_a, t_b, f_b, settings.tolerance * diagonal);
      return RayHit{start + t * d, d, t};
    }
    t_a = t_b;
    f_a = f_b;
  }
  return std::nullopt;
}

}  // namespace isopatch
