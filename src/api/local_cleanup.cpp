// The clean-up of the part of a mesh near some vertices (local_cleanup.hpp).
#include "api/local_cleanup.hpp"

#include "api/exact_positions.hpp"

#include <array>
#include <bit>
#include <cstddef>
#include <map>
#include <unordered_map>
#include <unordered_set>

namespace isopatch {

namespace {

std::uint64_t half_edge(std::uint32_t u, std::uint32_t v) {
  return (static_cast<std::uint64_t>(u) << 32) | v;
}

}  // namespace

std::vector<std::uint32_t> pinched_vertices(const std::vector<Triangle>& triangles) {
  std::unordered_set<std::uint64_t> half;
  for (const Triangle& t : triangles)
    for (std::size_t k = 0; k < 3; ++k) half.insert(half_edge(t[k], t[(k + 1) % 3]));
  std::map<std::uint32_t, int> leaving;
  for (const Triangle& t : triangles)
    for (std::size_t k = 0; k < 3; ++k)
      if (!half.count(half_edge(t[(k + 1) % 3], t[k]))) ++leaving[t[k]];
  std::vector<std::uint32_t> out;
  for (const auto& [v, count] : leaving)
    if (count > 1) out.push_back(v);
  return out;
}

void clean_up_near(Mesh& mesh, const Surface& surface, const std::vector<std::uint8_t>& seed, int rings,
                   RemeshSettings settings) {
  const std::size_t n = mesh.positions.size();
  std::vector<std::vector<std::uint32_t>> around(n);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::uint32_t v : mesh.triangles[t]) around[v].push_back(t);
  // The part: triangles within `rings` rings of the seeds.
  std::vector<std::uint8_t> near(seed);
  near.resize(n, 0);
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<std::uint8_t> next(near);
    for (std::size_t v = 0; v < n; ++v)
      if (near[v])
        for (std::uint32_t t : around[v])
          for (std::uint32_t w : mesh.triangles[t]) next[w] = 1;
    near.swap(next);
  }
  std::vector<std::uint8_t> in(mesh.triangles.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    in[t] = near[tri[0]] && near[tri[1]] && near[tri[2]] ? 1 : 0;
  }
  // Widened where its boundary pinches: every triangle at such a vertex joins.
  const auto part_triangles = [&] {
    std::vector<Triangle> out;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (in[t]) out.push_back(mesh.triangles[t]);
    return out;
  };
  for (std::vector<std::uint32_t> pinched = pinched_vertices(part_triangles()); !pinched.empty();
       pinched = pinched_vertices(part_triangles()))
    for (std::uint32_t v : pinched)
      for (std::uint32_t t : around[v]) in[t] = 1;
  Mesh part;
  std::vector<std::int64_t> local(n, -1);
  std::vector<std::uint32_t> global;
  std::vector<Triangle> rest;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!in[t]) {
      rest.push_back(mesh.triangles[t]);
      continue;
    }
    Triangle tri{};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[t][static_cast<std::size_t>(k)];
      if (local[v] < 0) {
        local[v] = static_cast<std::int64_t>(part.positions.size());
        global.push_back(v);
        part.positions.push_back(mesh.positions[v]);
      }
      tri[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(local[v]);
    }
    part.triangles.push_back(tri);
  }
  if (part.triangles.empty()) return;
  // Held vertices come back at the same positions: found by them.
  ExactPositionMap<std::uint32_t> old_id;
  for (std::size_t k = 0; k < global.size(); ++k) old_id.emplace(part.positions[k], global[k]);
  settings.hold_cut = true;
  remesh_on_surface(part, surface, settings);
  std::vector<std::uint32_t> id(part.positions.size());
  for (std::size_t k = 0; k < part.positions.size(); ++k) {
    const auto it = old_id.find(part.positions[k]);
    if (it != old_id.end()) {
      id[k] = it->second;
    } else {
      id[k] = static_cast<std::uint32_t>(mesh.positions.size());
      mesh.positions.push_back(part.positions[k]);
    }
  }
  mesh.triangles = std::move(rest);
  for (const Triangle& t : part.triangles) mesh.triangles.push_back({id[t[0]], id[t[1]], id[t[2]]});
}

}  // namespace isopatch
