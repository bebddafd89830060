/// \file polyhedron_topology.cpp
/// Topology checks and vertex fans of polygon meshes (polyhedron_topology.hpp).
#include "composite_model/polyhedron_topology.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>

namespace isopatch {

namespace {

std::string face_text(std::size_t f) {
  return "face " + std::to_string(f + 1);
}

std::string edge_text(std::uint32_t a, std::uint32_t b) {
  return "edge " + std::to_string(a + 1) + "-" + std::to_string(b + 1);
}

}  // namespace

Vec3 newell_normal(const PolygonMesh& mesh, std::size_t face) {
  const auto& f = mesh.faces[face];
  Vec3 n = Vec3::Zero();
  const Vec3 origin = mesh.vertices[f[0]];
  for (std::size_t i = 1; i + 1 < f.size(); ++i) {
    n += (mesh.vertices[f[i]] - origin).cross(mesh.vertices[f[i + 1]] - origin);
  }
  return n;
}

double signed_volume(const PolygonMesh& mesh) {
  double v = 0.0;
  for (const auto& f : mesh.faces) {
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
      v += mesh.vertices[f[0]].dot(mesh.vertices[f[i]].cross(mesh.vertices[f[i + 1]]));
    }
  }
  return v;
}

std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, std::uint32_t>> half_edges(
    const PolygonMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& face = mesh.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i) {
      out[{face[i], face[(i + 1) % face.size()]}] = {static_cast<std::uint32_t>(f),
                                                     static_cast<std::uint32_t>(i)};
    }
  }
  return out;
}

std::optional<TopologyProblem> find_topology_problem(const PolygonMesh& mesh) {
  if (mesh.vertices.size() < 4 || mesh.faces.size() < 4) {
    return TopologyProblem{std::nullopt, std::nullopt,
                           "a closed polyhedron needs at least 4 vertices and 4 faces"};
  }
  double extent = 0.0;
  for (const Vec3& v : mesh.vertices) extent = std::max(extent, v.cwiseAbs().maxCoeff());
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> directed;
  std::vector<std::size_t> uses(mesh.vertices.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& face = mesh.faces[f];
    if (face.size() < 3) return TopologyProblem{f, std::nullopt, face_text(f) + " has fewer than 3 vertices"};
    if (face.size() > kMaxFaceSides) {
      return TopologyProblem{f, std::nullopt,
                             face_text(f) + " has more than " + std::to_string(kMaxFaceSides) + " vertices"};
    }
    std::set<std::uint32_t> seen;
    for (std::uint32_t v : face) {
      if (v >= mesh.vertices.size()) {
        return TopologyProblem{
            f, std::nullopt,
            face_text(f) + " uses vertex " + std::to_string(v + 1) + ", which does not exist"};
      }
      if (!seen.insert(v).second) {
        return TopologyProblem{f, std::nullopt,
                               face_text(f) + " uses vertex " + std::to_string(v + 1) + " twice"};
      }
      ++uses[v];
    }
    const double area = newell_normal(mesh, f).norm();
    if (!(area > 1e-12 * extent * extent)) {
      return TopologyProblem{f, std::nullopt, face_text(f) + " has no area (its vertices are collinear)"};
    }
    for (std::size_t i = 0; i < face.size(); ++i) {
      const std::uint32_t a = face[i], b = face[(i + 1) % face.size()];
      auto [it, fresh] = directed.emplace(std::make_pair(a, b), f);
      if (!fresh) {
        return TopologyProblem{f, std::nullopt,
                               face_text(f) + " runs along " + edge_text(a, b) +
                                   " in the same direction as " + face_text(it->second) +
                                   " (faces inconsistently oriented, or the edge is non-manifold)"};
      }
    }
  }
  for (const auto& [edge, f] : directed) {
    if (!directed.count({edge.second, edge.first})) {
      return TopologyProblem{f, std::nullopt,
                             "the polyhedron is open: " + edge_text(edge.first, edge.second) + " of " +
                                 face_text(f) + " has no opposite face"};
    }
  }
  const std::vector<VertexFan> fans = vertex_fans(mesh);
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) {
    if (uses[v] == 0) {
      return TopologyProblem{std::nullopt, v, "vertex " + std::to_string(v + 1) + " is used by no face"};
    }
    if (fans[v].faces.size() != uses[v]) {
      return TopologyProblem{std::nullopt, v,
                             "the faces around vertex " + std::to_string(v + 1) +
                                 " form more than one fan (a non-manifold vertex)"};
    }
  }
  return std::nullopt;
}

std::vector<VertexFan> vertex_fans(const PolygonMesh& mesh) {
  // From any face holding v: the half-edge (v -> w) lies in face F; the vertex before v in F, u, gives
  // the next half-edge (v -> u), in the next face.
  const auto edges = half_edges(mesh);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> first(mesh.vertices.size(), {UINT32_MAX, 0});
  for (std::size_t f = mesh.faces.size(); f-- > 0;) {
    for (std::size_t i = 0; i < mesh.faces[f].size(); ++i) {
      const std::uint32_t v = mesh.faces[f][i];
      if (v < first.size()) first[v] = {static_cast<std::uint32_t>(f), static_cast<std::uint32_t>(i)};
    }
  }
  std::vector<VertexFan> fans(mesh.vertices.size());
  for (std::uint32_t vertex = 0; vertex < mesh.vertices.size(); ++vertex) {
    auto [face, pos] = first[vertex];
    if (face == UINT32_MAX) continue;
    const std::uint32_t start_face = face;
    VertexFan& fan = fans[vertex];
    for (std::size_t guard = 0; guard <= mesh.faces.size(); ++guard) {
      const auto& f = mesh.faces[face];
      fan.neighbours.push_back(f[(pos + 1) % f.size()]);
      fan.faces.push_back(face);
      const std::uint32_t before = f[(pos + f.size() - 1) % f.size()];
      const auto it = edges.find({vertex, before});
      if (it == edges.end()) break;  // open: reported by find_topology_problem
      face = it->second.first;
      pos = it->second.second;
      if (face == start_face) break;
    }
  }
  return fans;
}

}  // namespace isopatch
