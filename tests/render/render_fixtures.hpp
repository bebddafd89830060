#pragma once
// Small meshes and pixel helpers for the renderer's tests.

#include <isopatch/mesh.hpp>
#include <isopatch/render.hpp>

#include <cmath>
#include <cstdlib>
#include <numbers>

namespace isopatch::test {

/// A latitude-longitude sphere of radius r about the origin, outward-oriented (counter-clockwise seen
/// from outside), with `rings` bands of latitude and `sectors` of longitude.
inline Mesh uv_sphere(double r = 1.0, int rings = 24, int sectors = 48) {
  Mesh mesh;
  const double pi = std::numbers::pi;
  mesh.positions.emplace_back(0.0, 0.0, r);  // north pole
  for (int i = 1; i < rings; ++i) {
    const double theta = pi * i / rings;
    for (int j = 0; j < sectors; ++j) {
      const double phi = 2.0 * pi * j / sectors;
      mesh.positions.emplace_back(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                                  r * std::cos(theta));
    }
  }
  mesh.positions.emplace_back(0.0, 0.0, -r);  // south pole
  const auto south = static_cast<std::uint32_t>(mesh.positions.size() - 1);
  auto ring = [&](int i, int j) { return static_cast<std::uint32_t>(1 + (i - 1) * sectors + (j % sectors)); };
  for (int j = 0; j < sectors; ++j) mesh.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      mesh.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      mesh.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  for (int j = 0; j < sectors; ++j)
    mesh.triangles.push_back({south, ring(rings - 1, j + 1), ring(rings - 1, j)});
  return mesh;
}

/// The square {x = x0, |y| <= h, |z| <= h} as two triangles, facing +x (towards a camera at azimuth 0,
/// elevation 0).
inline Mesh square_facing_x(double h = 1.0, double x0 = 0.0) {
  Mesh mesh;
  mesh.positions = {Vec3(x0, -h, -h), Vec3(x0, h, -h), Vec3(x0, h, h), Vec3(x0, -h, h)};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

/// Number of pixels that differ from `colour`.
inline int count_other_than(const Image& image, Rgb colour) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) n += image.at(x, y) == colour ? 0 : 1;
  return n;
}

/// Largest per-channel difference between two colours.
inline int channel_distance(Rgb a, Rgb b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

inline int brightness(Rgb c) {
  return c.r + c.g + c.b;
}

}  // namespace isopatch::test
