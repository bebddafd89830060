// Umbrella-operator smoothing with projection back onto f = 0 (the paper's Figure 2 baseline).
#include <isopatch/error.hpp>
#include <isopatch/fairing.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "surface/project_point.hpp"
#include "surface/sampler.hpp"

namespace isopatch {
namespace {

/// Neighbour lists in compressed form, and a flag for vertices on boundary edges.
struct Adjacency {
  std::vector<std::size_t> offsets;
  std::vector<std::uint32_t> neighbours;
  std::vector<bool> on_boundary;
};

Adjacency build_adjacency(const Mesh& mesh) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> directed;
  directed.reserve(mesh.triangles.size() * 3);
  for (const Triangle& t : mesh.triangles)
    for (std::size_t i = 0; i < 3; ++i) directed.emplace_back(t[i], t[(i + 1) % 3]);
  // An undirected edge is on the boundary when only one of its two directions occurs.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> undirected;
  undirected.reserve(directed.size());
  for (const auto& [a, b] : directed) undirected.emplace_back(std::min(a, b), std::max(a, b));
  std::sort(undirected.begin(), undirected.end());
  Adjacency adj;
  adj.on_boundary.assign(mesh.positions.size(), false);
  std::vector<std::vector<std::uint32_t>> lists(mesh.positions.size());
  for (std::size_t i = 0; i < undirected.size();) {
    std::size_t j = i;
    while (j < undirected.size() && undirected[j] == undirected[i]) ++j;
    const auto [a, b] = undirected[i];
    if (j - i == 1) adj.on_boundary[a] = adj.on_boundary[b] = true;
    lists[a].push_back(b);
    lists[b].push_back(a);
    i = j;
  }
  adj.offsets.push_back(0);
  for (const auto& l : lists) {
    adj.neighbours.insert(adj.neighbours.end(), l.begin(), l.end());
    adj.offsets.push_back(adj.neighbours.size());
  }
  return adj;
}

}  // namespace

FairingStats laplace_fair(Mesh& mesh, const Surface& surface, int iterations) {
  if (iterations < 0 || iterations > 10000)
    throw InputError("fairing iterations must be between 0 and 10000, got " + std::to_string(iterations));
  FairingStats stats;
  if (iterations == 0 || mesh.positions.empty()) return stats;
  const Adjacency adj = build_adjacency(mesh);
  const Sampler f(surface);
  const double tolerance = 1e-13 * bounding_box(mesh).diagonal();
  std::vector<Vec3> next(mesh.positions.size());
  for (int it = 0; it < iterations; ++it) {
    stats.unconverged = 0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const std::size_t begin = adj.offsets[v], end = adj.offsets[v + 1];
      if (adj.on_boundary[v] || begin == end) {
        next[v] = mesh.positions[v];
        continue;
      }
      Vec3 centroid = Vec3::Zero();
      double longest = 0.0;
      for (std::size_t k = begin; k < end; ++k) {
        centroid += mesh.positions[adj.neighbours[k]];
        longest = std::max(longest, (mesh.positions[adj.neighbours[k]] - mesh.positions[v]).norm());
      }
      centroid /= static_cast<double>(end - begin);
      Vec3 p = centroid;
      if (!project_to_surface(f, p, tolerance, std::max(longest, tolerance))) {
        ++stats.unconverged;
        p = mesh.positions[v];  // keep the previous (projected) position
      }
      next[v] = p;
    }
    std::swap(mesh.positions, next);
  }
  stats.gradient_evaluations = f.gradient_count();
  return stats;
}

}  // namespace isopatch
