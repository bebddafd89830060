#include "render/shading.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace isopatch::render {

Colour shaded_colour(const Colour& base, const Vec3& normal, const Lighting& lighting) {
  const Vec3 l = lighting.direction.normalized();
  const Vec3 h = (l + Vec3::UnitZ()).normalized();
  const double highlight = normal.dot(h) > 0.0 ? std::pow(normal.dot(h), lighting.shininess) : 0.0;
  return base * (lighting.ambient + lighting.diffuse * std::max(0.0, normal.dot(l))) +
         Colour::Constant(lighting.specular * highlight);
}

Colour field_colour(const Colour& base, const Vec3& normal, const Lighting& lighting) {
  const Vec3 l = lighting.direction.normalized();
  return base * (lighting.field_ambient + (1.0 - lighting.field_ambient) * std::max(0.0, normal.dot(l)));
}

int isophote_stripe(const Vec3& normal, const Vec3& light, int stripes) {
  // Equal steps of angle rather than of the cosine, so the stripes have even widths.
  const double angle = std::acos(std::clamp(normal.dot(light), -1.0, 1.0));
  const int k = static_cast<int>(std::floor(stripes * angle / std::numbers::pi));
  return std::clamp(k, 0, stripes - 1);
}

Rgb to_rgb8(const Colour& colour) {
  auto channel = [](double v) {
    // NaN maps to 0 through the comparison below; clamping is the definition of display colour.
    const double clamped = v > 0.0 ? std::min(v, 1.0) : 0.0;
    return static_cast<std::uint8_t>(std::lround(255.0 * clamped));
  };
  return Rgb{channel(colour.x()), channel(colour.y()), channel(colour.z())};
}

}  // namespace isopatch::render
