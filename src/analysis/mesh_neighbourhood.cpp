// Edges are found by sorting the undirected keys of all half-edges: equal keys sit together, so one
// pass gives each distinct edge with the number of triangles that contain it. This keeps memory at
// O(F) and avoids building a half-edge structure that the metrics do not need.
#include "mesh_neighbourhood.hpp"

#include <isopatch/error.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace isopatch::analysis {

void check_mesh(const Mesh& mesh, const std::string& where) {
  const std::size_t n = mesh.positions.size();
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw InputError(where + ": mesh too large for 32-bit indices");
  for (std::size_t v = 0; v < n; ++v)
    if (!mesh.positions[v].allFinite())
      throw InputError(where + ": vertex " + std::to_string(v) + " is not finite");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::uint32_t i : mesh.triangles[t])
      if (i >= n)
        throw InputError(where + ": triangle " + std::to_string(t) + " refers to vertex " +
                         std::to_string(i) + " of " + std::to_string(n));
}

MeshNeighbourhood mesh_neighbourhood(const Mesh& mesh) {
  const std::size_t n = mesh.positions.size();
  MeshNeighbourhood result;
  result.valence.assign(n, 0);
  result.referenced.assign(n, false);
  result.interior.assign(n, false);

  std::vector<std::uint64_t> keys;
  keys.reserve(3 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    if (repeats_vertex(t)) continue;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k];
      const std::uint32_t b = t[(k + 1) % 3];
      keys.push_back((std::uint64_t{std::min(a, b)} << 32) | std::max(a, b));
      result.referenced[a] = true;
    }
  }
  std::sort(keys.begin(), keys.end());

  for (std::size_t begin = 0; begin < keys.size();) {
    std::size_t end = begin + 1;
    while (end < keys.size() && keys[end] == keys[begin]) ++end;
    Edge e;
    e.a = static_cast<std::uint32_t>(keys[begin] >> 32);
    e.b = static_cast<std::uint32_t>(keys[begin] & 0xffffffffu);
    e.triangles = static_cast<std::uint32_t>(end - begin);
    result.edges.push_back(e);
    begin = end;
  }

  // A vertex starts interior when referenced and loses it on any edge not shared by exactly two.
  result.interior = result.referenced;
  for (const Edge& e : result.edges) {
    ++result.valence[e.a];
    ++result.valence[e.b];
    if (e.triangles != 2) result.interior[e.a] = result.interior[e.b] = false;
  }
  return result;
}

std::vector<Vec3> area_weighted_normals(const Mesh& mesh) {
  std::vector<Vec3> normals(mesh.positions.size(), Vec3::Zero());
  for (const Triangle& t : mesh.triangles) {
    if (repeats_vertex(t)) continue;
    const Vec3& a = mesh.positions[t[0]];
    const Vec3 n = (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
    for (std::uint32_t v : t) normals[v] += n;
  }
  return normals;
}

}  // namespace isopatch::analysis
