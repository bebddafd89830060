#pragma once
// Benchmark surfaces written as C++ callables (independent of the expression language), so the
// meshers can be tested on them and the formula versions can be checked against them.

#include <isopatch/callable_surface.hpp>

#include <cmath>

namespace isopatch::test {

inline SurfacePtr sphere(double radius = 1.0, Vec3 centre = Vec3::Zero(), double box_half = 1.2) {
  const double cx = centre.x(), cy = centre.y(), cz = centre.z();
  return make_surface(
      [=](auto x, auto y, auto z) {
        return (x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz) - radius * radius;
      },
      Box{centre - Vec3::Constant(box_half), centre + Vec3::Constant(box_half)}, "sphere");
}

inline SurfacePtr torus(double R = 1.0, double r = 0.4) {
  return make_surface(
      [=](auto x, auto y, auto z) {
        auto q = x * x + y * y + z * z + R * R - r * r;
        return q * q - 4.0 * R * R * (x * x + y * y);
      },
      Box{Vec3(-1.6, -1.6, -0.6), Vec3(1.6, 1.6, 0.6)}, "torus");
}

inline SurfacePtr tanglecube() {
  return make_surface(
      [](auto x, auto y, auto z) {
        auto x2 = x * x, y2 = y * y, z2 = z * z;
        return x2 * x2 - 5.0 * x2 + y2 * y2 - 5.0 * y2 + z2 * z2 - 5.0 * z2 + 11.8;
      },
      Box{Vec3::Constant(-2.6), Vec3::Constant(2.6)}, "tanglecube");
}

inline SurfacePtr genus2() {
  return make_surface(
      [](auto x, auto y, auto z) {
        auto x2 = x * x, y2 = y * y;
        auto a = (x2 + y2) * (x2 + y2) - x2 + y2;
        return a * a + z * z - 0.01;
      },
      Box{Vec3(-1.2, -0.5, -0.15), Vec3(1.2, 0.5, 0.15)}, "genus2");
}

}  // namespace isopatch::test
