/// \file fan_centre.cpp
/// The centre of a fallback fan (fan_centre.hpp).
#include "projection/fan_centre.hpp"

#include <optional>

#include "projection/ray_march.hpp"

namespace isopatch {

FanCentre fan_centre(const Sampler& f, std::span<const Vec3> polygon, const Vec3& direction,
                     const MarchRegion& region, int march_steps) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : polygon) centre += p;
  centre /= static_cast<double>(polygon.size());
  RayMarchSettings march;
  march.steps = march_steps;
  const double f_centre = f.value(centre);
  std::optional<RayHit> hit;
  if (direction.norm() > 0.0) hit = march_to_surface(f, centre, f_centre, direction, region, march);
  if (!hit) hit = march_to_surface(f, centre, f_centre, f.value_gradient(centre).gradient, region, march);
  if (!hit) return {{centre, direction}, false};
  return {{hit->point, f.value_gradient(hit->point).gradient}, true};
}

}  // namespace isopatch
