#pragma once
// Checks shared by the tests of meshes along creases: a formula meshed with settings, the faces its
// vertices lie on, dihedral angles across crease edges.

#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <isopatch/expression.hpp>

#include <set>

#include "csg/csg_composite.hpp"
#include "csg/face_set.hpp"

namespace isopatch::test {

struct CsgRun {
  SurfacePtr surface;
  Mesh mesh;
  MeshStats stats;
  std::vector<SurfacePtr> faces;      ///< the face functions of the shape (from the analysis)
  std::shared_ptr<FaceSet> face_set;  ///< the analysis' faces
};

inline CsgRun mesh_csg(const std::string& formula, const Box& box, Settings settings = {}) {
  CsgRun run;
  run.surface = expression_surface(formula, box);
  settings.box = box;
  run.mesh = mesh_surface(*run.surface, settings, &run.stats);
  const TargetSizes sizes = target_sizes(settings, box);
  if (const std::optional<CsgShape> shape = analyse_csg(*run.surface, box, sizes.largest)) {
    run.faces = shape->face_functions;
    run.face_set = shape->face_set;
  }
  return run;
}

inline double distance_to(const Surface& f, const Vec3& p) {
  const ValueGradient g = f.value_gradient(p);
  return std::abs(g.value) / g.gradient.norm();
}

/// The vertices where triangles of different faces meet (each triangle's face is the analysis' face
/// at its centroid moved onto f = 0), and the largest distance from such a vertex to the functions of
/// the faces of its triangles: every crease vertex must lie on both faces, every corner on all three.
/// Returns (largest distance, crease vertices).
inline std::pair<double, std::size_t> crease_residual(const CsgRun& run) {
  FaceSet& faces = *run.face_set;
  const Mesh& mesh = run.mesh;
  std::vector<std::set<int>> around(mesh.vertex_count());
  for (const Triangle& t : mesh.triangles) {
    Vec3 c = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
    for (int k = 0; k < 3; ++k) {
      const ValueGradient g = run.surface->value_gradient(c);
      c -= g.value / g.gradient.squaredNorm() * g.gradient;
    }
    const int face = faces.face_at(c);
    for (const std::uint32_t v : t) around[v].insert(face);
  }
  double worst = 0.0;
  std::size_t count = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (around[v].size() < 2) continue;
    ++count;
    for (const int face : around[v])
      worst = std::max(worst, distance_to(*faces.function(face), mesh.positions[v]));
  }
  return {worst, count};
}

/// Mean |dihedral - exact| (degrees) over the mesh edges whose ends both lie on faces a and b (to
/// `on`): the angle between the two triangles' normals against the angle between grad a and grad b at
/// the edge's midpoint.
inline double dihedral_error(const Mesh& mesh, const Surface& a, const Surface& b, double on) {
  std::vector<bool> crease(mesh.vertex_count());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    crease[v] = distance_to(a, mesh.positions[v]) <= on && distance_to(b, mesh.positions[v]) <= on;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<Vec3>> normals;
  for (const Triangle& t : mesh.triangles) {
    const Vec3 n = (mesh.positions[t[1]] - mesh.positions[t[0]])
                       .cross(mesh.positions[t[2]] - mesh.positions[t[0]])
                       .normalized();
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = t[static_cast<std::size_t>(k)], v = t[static_cast<std::size_t>((k + 1) % 3)];
      if (crease[u] && crease[v]) normals[{std::min(u, v), std::max(u, v)}].push_back(n);
    }
  }
  double sum = 0.0;
  std::size_t count = 0;
  for (const auto& [edge, n] : normals) {
    if (n.size() != 2) continue;
    const Vec3 m = 0.5 * (mesh.positions[edge.first] + mesh.positions[edge.second]);
    const double exact = std::acos(std::clamp(
        a.value_gradient(m).gradient.normalized().dot(b.value_gradient(m).gradient.normalized()), -1.0, 1.0));
    const double measured = std::acos(std::clamp(n[0].dot(n[1]), -1.0, 1.0));
    sum += std::abs(measured - exact) * 180.0 / std::numbers::pi;
    ++count;
  }
  return count ? sum / static_cast<double>(count) : -1.0;
}

}  // namespace isopatch::test
