#pragma once
// Composites built in the tests, independent of the .ipatch reader: a convex polyhedron inscribed in a
// sphere becomes one patch per face, each patch the sphere itself inside the pyramid over its face
// (bounded by the planes through the centre and each edge), each edge a great-circle arc. Neighbours
// share their bounding plane and function, so the composite is exactly the sphere: the octahedron
// gives 8 three-sided octants of the unit sphere, the cube 6 four-sided patches of radius sqrt(3).

#include <isopatch/callable_surface.hpp>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "composite_model/composite.hpp"

namespace isopatch::test {

inline std::shared_ptr<Composite> inscribed_sphere_composite(const std::vector<Vec3>& vertices,
                                                             const std::vector<std::vector<int>>& faces,
                                                             std::string name) {
  const double radius = vertices[0].norm();
  auto c = std::make_shared<Composite>();
  c->name = std::move(name);
  c->box = Box{Vec3::Constant(-1.25 * radius), Vec3::Constant(1.25 * radius)};
  const SurfacePtr sphere = make_surface(
      [=](auto x, auto y, auto z) { return (x * x + y * y + z * z - radius * radius) / (2.0 * radius); },
      c->box, "sphere");
  std::map<std::pair<int, int>, std::uint32_t> curve_of;
  for (const auto& face : faces) {
    CompositePatch patch;
    patch.name = "face " + std::to_string(c->patches.size());
    patch.surface = sphere;
    Vec3 centroid = Vec3::Zero();
    for (const int v : face) centroid += vertices[static_cast<std::size_t>(v)];
    for (std::size_t k = 0; k < face.size(); ++k) {
      const int i = face[k], j = face[(k + 1) % face.size()];
      const Vec3& a = vertices[static_cast<std::size_t>(std::min(i, j))];
      const Vec3& b = vertices[static_cast<std::size_t>(std::max(i, j))];
      auto [it, fresh] = curve_of.emplace(std::make_pair(std::min(i, j), std::max(i, j)),
                                          static_cast<std::uint32_t>(c->curves.size()));
      if (fresh) {
        const double half = 0.5 * std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
        c->curves.push_back({a, (a + b).normalized() * radius / std::cos(half), b, std::cos(half)});
      }
      patch.sides.push_back({it->second, i > j});
      patch.corner_directions.push_back(vertices[static_cast<std::size_t>(i)].normalized());
      Vec3 n = a.cross(b).normalized();
      if (n.dot(centroid) < 0.0) n = -n;
      patch.bounds.push_back(make_surface(
          [=](auto x, auto y, auto z) { return n.x() * x + n.y() * y + n.z() * z; }, c->box, "bound"));
    }
    c->patches.push_back(std::move(patch));
  }
  return c;
}

/// The cube [-1, 1]^3 itself as six planar patches in the same pyramids: straight edges, 90 degree
/// creases at every seam (not G1), for the measures that must tell a crease from a smooth seam.
inline std::shared_ptr<Composite> creased_cube() {
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 4 ? 1 : -1, i & 2 ? 1 : -1, i & 1 ? 1 : -1);
  const std::vector<std::vector<int>> f{{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                        {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  auto c = inscribed_sphere_composite(v, f, "creased cube");
  for (ConicArc& a : c->curves) {
    a.control = 0.5 * (a.start + a.end);
    a.weight = 1.0;
  }
  for (std::size_t k = 0; k < f.size(); ++k) {
    Vec3 n = Vec3::Zero();
    for (const int i : f[k]) n += v[static_cast<std::size_t>(i)];
    n /= 4.0;
    c->patches[k].surface = make_surface(
        [=](auto x, auto y, auto z) { return n.x() * x + n.y() * y + n.z() * z - 1.0; }, c->box, "face");
    for (Vec3& d : c->patches[k].corner_directions) d = n;
  }
  return c;
}

inline std::shared_ptr<Composite> octahedron_sphere() {
  const std::vector<Vec3> v{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  // Counter-clockwise seen from outside.
  const std::vector<std::vector<int>> f{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                        {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return inscribed_sphere_composite(v, f, "octahedron sphere");
}

inline std::shared_ptr<Composite> cube_sphere() {
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 4 ? 1 : -1, i & 2 ? 1 : -1, i & 1 ? 1 : -1);
  const std::vector<std::vector<int>> f{{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                        {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  return inscribed_sphere_composite(v, f, "cube sphere");
}

}  // namespace isopatch::test
