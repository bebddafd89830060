#pragma once
// Small meshes with known geometry for the metrics tests, built in code: a regular icosahedron (found
// from its vertices, not from a pasted face table), its subdivisions projected onto a sphere, a flat
// hexagonal fan, a parametric torus and a triangulated square on a tilted plane; and any of them with
// vertices moved at random.

#include <isopatch/mesh.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <random>
#include <utility>

namespace isopatch::test {

/// The regular icosahedron with vertices (0, +-1, +-phi) and cyclic permutations (edge length 2),
/// outward oriented. Its faces are the triples of vertices at mutual distance 2.
inline Mesh icosahedron() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh m;
  for (double s : {-1.0, 1.0})
    for (double t : {-phi, phi}) {
      m.positions.emplace_back(0.0, s, t);
      m.positions.emplace_back(s, t, 0.0);
      m.positions.emplace_back(t, 0.0, s);
    }
  auto adjacent = [&](std::size_t i, std::size_t j) {
    return std::abs((m.positions[i] - m.positions[j]).norm() - 2.0) < 1e-9;
  };
  const std::size_t n = m.positions.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        if (!adjacent(i, j) || !adjacent(j, k) || !adjacent(i, k)) continue;
        const Vec3 normal = (m.positions[j] - m.positions[i]).cross(m.positions[k] - m.positions[i]);
        const Vec3 centroid = m.positions[i] + m.positions[j] + m.positions[k];
        const auto a = static_cast<std::uint32_t>(i), b = static_cast<std::uint32_t>(j),
                   c = static_cast<std::uint32_t>(k);
        if (normal.dot(centroid) > 0)
          m.triangles.push_back({a, b, c});
        else
          m.triangles.push_back({a, c, b});
      }
  return m;
}

/// The icosahedron split `levels` times (each triangle into four at the edge midpoints) with every
/// vertex pushed radially onto the sphere of `radius` about the origin.
inline Mesh icosphere(int levels, double radius = 1.0) {
  Mesh m = icosahedron();
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
    auto middle = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto found = midpoint.find(key);
      if (found != midpoint.end()) return found->second;
      const auto index = static_cast<std::uint32_t>(m.positions.size());
      m.positions.push_back(0.5 * (m.positions[a] + m.positions[b]));
      midpoint.emplace(key, index);
      return index;
    };
    std::vector<Triangle> finer;
    for (const Triangle& t : m.triangles) {
      const std::uint32_t ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({ab, t[1], bc});
      finer.push_back({ca, bc, t[2]});
      finer.push_back({ab, bc, ca});
    }
    m.triangles = std::move(finer);
  }
  for (Vec3& p : m.positions) p *= radius / p.norm();
  return m;
}

/// Six equilateral triangles (side 1) around the origin in the plane z = 0, normals along +z.
inline Mesh hexagon_fan() {
  Mesh m;
  m.positions.push_back(Vec3::Zero());
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3.0;
    m.positions.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  for (std::uint32_t k = 0; k < 6; ++k) m.triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
  return m;
}

/// The torus of revolution (radii R, r) on an m x n grid of its angles, two triangles per quad, so
/// every vertex has valence 6; outward oriented. With jitter > 0 every grid angle moves by a
/// pseudo-random amount in +-jitter/2 of a grid step (fixed seed): same connectivity, still exactly on
/// the torus, but irregular sampling.
inline Mesh parametric_torus(int m, int n, double R = 1.0, double r = 0.4, double jitter = 0.0) {
  std::minstd_rand random(12345);  // fully specified by the standard: the same numbers everywhere
  auto offset = [&] { return jitter * (static_cast<double>(random() - 1) / 2147483645.0 - 0.5); };
  Mesh mesh;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = 2 * std::numbers::pi * (i + offset()) / m;
      const double v = 2 * std::numbers::pi * (j + offset()) / n;
      mesh.positions.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                                  r * std::sin(v));
    }
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % m) * n + (j % n)); };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh;
}

/// A triangulated square of n x n vertices in the tilted plane z = 0.3 x + 0.7 y + 0.1: rounding leaves
/// its vertices a few ulps off one plane, where double-precision orientation signs are noise.
inline Mesh tilted_grid(int n) {
  Mesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = i / (n - 1.0), y = j / (n - 1.0);
      m.positions.emplace_back(x, y, 0.3 * x + 0.7 * y + 0.1);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const auto v = static_cast<std::uint32_t>(j * n + i), w = static_cast<std::uint32_t>(n);
      m.triangles.push_back({v, v + 1, v + w + 1});
      m.triangles.push_back({v, v + w + 1, v + w});
    }
  return m;
}

/// `m` with `moved` vertices picked at random (with repeats) moved by up to `reach` in each coordinate,
/// from the seed `seed`: folds and overlaps for the self-intersection tests.
inline Mesh jittered(Mesh m, int moved, double reach, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, m.positions.size() - 1);
  std::uniform_real_distribution<double> offset(-reach, reach);
  for (int k = 0; k < moved; ++k) m.positions[pick(rng)] += Vec3(offset(rng), offset(rng), offset(rng));
  return m;
}

}  // namespace isopatch::test
