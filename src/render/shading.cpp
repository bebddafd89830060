#include "render/shading.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace isopatch::render {

std::vector<Vec3> vertex_normals(const Mesh& mesh) {
  std::vector<Vec3> normals(mesh.vertex_count(), Vec3::Zero());
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.positions[t[0]];
    // Twice the area times the unit normal: larger triangles weigh more.
    const Vec3 n = (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
    for (const std::uint32_t v : t) normals[v] += n;
  }
  for (Vec3& n : normals) {
    const double length = n.norm();
    n = length > 0.0 ? Vec3(n / length) : Vec3::Zero();
  }
  return normals;
}

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
