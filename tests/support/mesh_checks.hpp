#pragma once
// Invariant checks on output meshes shared by the mesher tests: distance to f = 0, valences, angles.

#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

namespace isopatch::test {

/// Largest first-order distance |f| / |grad f| over the vertices.
inline double max_vertex_distance(const Surface& s, const Mesh& mesh) {
  double worst = 0.0;
  for (const Vec3& p : mesh.positions) {
    const ValueGradient vg = s.value_gradient(p);
    worst = std::max(worst, std::abs(vg.value) / vg.gradient.norm());
  }
  return worst;
}

/// The volume a closed, outward mesh encloses (the divergence theorem over its triangles).
inline double enclosed_volume(const Mesh& mesh) {
  double v = 0.0;
  for (const Triangle& t : mesh.triangles)
    v += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]])) / 6.0;
  return v;
}

/// The vertices of the boundary edges (edges of exactly one triangle), ascending.
inline std::set<std::uint32_t> boundary_vertices(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const Triangle& tri : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = tri[static_cast<std::size_t>(i)],
                          b = tri[static_cast<std::size_t>((i + 1) % 3)];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::set<std::uint32_t> boundary;
  for (const auto& [edge, n] : uses)
    if (n == 1) boundary.insert({edge.first, edge.second});
  return boundary;
}

/// Number of distinct neighbours of every vertex.
inline std::vector<int> valences(const Mesh& mesh) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const auto a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  std::vector<int> v(mesh.positions.size(), 0);
  for (const auto& [a, b] : edges) {
    ++v[a];
    ++v[b];
  }
  return v;
}

/// Smallest interior angle over all triangles, in degrees.
inline double min_angle_degrees(const Mesh& mesh) {
  double worst = 180.0;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const Vec3& a = mesh.positions[t[static_cast<std::size_t>(i)]];
      const Vec3& b = mesh.positions[t[static_cast<std::size_t>((i + 1) % 3)]];
      const Vec3& c = mesh.positions[t[static_cast<std::size_t>((i + 2) % 3)]];
      const double cosine = (b - a).normalized().dot((c - a).normalized());
      worst = std::min(worst, std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi);
    }
  return worst;
}

}  // namespace isopatch::test
