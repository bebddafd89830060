/// \file composite_quality.cpp
/// Quality of a composite's mesh by patch and across seams (composite_quality.hpp).
#include "analysis/composite_quality.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

#include "core/triangle_angle.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

namespace {

using EdgeTriangles = std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>>;

double angle_degrees(const Vec3& a, const Vec3& b) {
  const double c = a.normalized().dot(b.normalized());
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

/// The worst seam ratio (CompositeQuality::worst_seam_ratio) with triangle normals from `normal`;
/// adds the mean jumps to `q` when `count` is set.
template <class Normal>
double seam_ratio(const CompositeMesh& m, const EdgeTriangles& edge_triangles, double diagonal,
                  Normal&& normal, CompositeQuality* count) {
  const auto& pos = m.mesh.positions;
  // The jump at every edge with two triangles, in degrees per unit length.
  std::map<std::pair<std::uint32_t, std::uint32_t>, double> jump_at;
  for (const auto& [edge, triangles] : edge_triangles) {
    const double length = (pos[edge.first] - pos[edge.second]).norm();
    if (triangles.size() != 2 || !(length > 0.0)) continue;
    jump_at[edge] = angle_degrees(normal(triangles[0]), normal(triangles[1])) / length;
  }
  double seam_sum = 0.0, patch_sum = 0.0;
  std::size_t seam_edges = 0, patch_edges = 0;
  // Per pair of patches: the jumps across their seam, and those at the patch edges next to it (the
  // other edges of the two triangles at each seam edge), which see the surface's own turning there.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::array<double, 4>> seams;  // sum, n, near sum, near n
  for (const auto& [edge, jump] : jump_at) {
    const auto& triangles = edge_triangles.at(edge);
    const std::uint32_t a = m.triangle_patch[triangles[0]], b = m.triangle_patch[triangles[1]];
    if (a == b) {
      patch_sum += jump;
      ++patch_edges;
      continue;
    }
    seam_sum += jump;
    ++seam_edges;
    auto& seam = seams[{std::min(a, b), std::max(a, b)}];
    seam[0] += jump;
    seam[1] += 1.0;
    for (const std::size_t t : triangles)
      for (std::size_t i = 0; i < 3; ++i) {
        const std::uint32_t u = m.mesh.triangles[t][i], v = m.mesh.triangles[t][(i + 1) % 3];
        const auto other = jump_at.find({std::min(u, v), std::max(u, v)});
        if (other == jump_at.end() || other->first == edge) continue;
        const auto& ts = edge_triangles.at(other->first);
        if (m.triangle_patch[ts[0]] != m.triangle_patch[ts[1]]) continue;
        seam[2] += other->second;
        seam[3] += 1.0;
      }
  }
  const double floor = 1.0 / diagonal;
  double worst = 0.0;
  for (const auto& [pair, seam] : seams) {
    const double near = seam[3] > 0.0 ? seam[2] / seam[3] : 0.0;
    worst = std::max(worst, seam[0] / seam[1] / std::max(near, floor));
  }
  if (count) {
    count->seam_edges = seam_edges;
    count->patch_edges = patch_edges;
    count->seam_normal_jump = seam_edges ? seam_sum / static_cast<double>(seam_edges) : 0.0;
    count->patch_normal_jump = patch_edges ? patch_sum / static_cast<double>(patch_edges) : 0.0;
  }
  return worst;
}

}  // namespace

CompositeQuality measure_composite_mesh(const Composite& composite, const CompositeMesh& m) {
  CompositeQuality q;
  const auto& pos = m.mesh.positions;
  const std::size_t nv = pos.size();
  std::vector<std::set<std::uint32_t>> neighbours(nv);
  std::vector<std::set<std::uint32_t>> vertex_patches(nv);
  EdgeTriangles edge_triangles;
  q.min_angle = 180.0;
  q.patch_min_angle = 180.0;
  for (std::size_t t = 0; t < m.mesh.triangles.size(); ++t) {
    const Triangle& tri = m.mesh.triangles[t];
    bool on_curve = false;
    for (std::size_t i = 0; i < 3; ++i) {
      const std::uint32_t a = tri[i], b = tri[(i + 1) % 3];
      neighbours[a].insert(b);
      neighbours[b].insert(a);
      vertex_patches[a].insert(m.triangle_patch[t]);
      edge_triangles[{std::min(a, b), std::max(a, b)}].push_back(t);
      on_curve = on_curve || m.vertex_patch[a] < 0;
    }
    const double angle = smallest_angle(pos[tri[0]], pos[tri[1]], pos[tri[2]]);
    q.min_angle = std::min(q.min_angle, angle);
    if (!on_curve) q.patch_min_angle = std::min(q.patch_min_angle, angle);
  }
  std::size_t valence_6 = 0;
  for (std::size_t v = 0; v < nv; ++v)
    if (m.vertex_patch[v] >= 0) {
      ++q.patch_vertices;
      if (neighbours[v].size() == 6) ++valence_6;
    }
  q.patch_valence_6 =
      q.patch_vertices ? static_cast<double>(valence_6) / static_cast<double>(q.patch_vertices) : 1.0;

  const double diagonal = composite.box.diagonal();
  std::vector<std::unique_ptr<Sampler>> f;
  for (const CompositePatch& p : composite.patches) f.push_back(std::make_unique<Sampler>(*p.surface));
  // The corners: curve vertices at a curve's end (anywhere in the vertex order: a refined mesh puts
  // its curve points among the others).
  std::set<std::array<double, 3>> curve_ends;
  for (const ConicArc& a : composite.curves) {
    curve_ends.insert({a.start.x(), a.start.y(), a.start.z()});
    curve_ends.insert({a.end.x(), a.end.y(), a.end.z()});
  }
  std::set<std::uint32_t> corners;
  for (std::uint32_t v = 0; v < nv; ++v)
    if (m.vertex_patch[v] < 0 && curve_ends.count({pos[v].x(), pos[v].y(), pos[v].z()})) corners.insert(v);
  for (std::uint32_t v = 0; v < nv; ++v) {
    std::vector<Vec3> gradients;
    for (const std::uint32_t p : vertex_patches[v]) {
      const ValueGradient vg =
          corners.count(v) ? f[p]->value_gradient_unchecked(pos[v]) : f[p]->value_gradient(pos[v]);
      const double g = vg.gradient.norm();
      if (!std::isfinite(vg.value) || !(g > 0.0) || !std::isfinite(g)) continue;
      q.max_relative_distance = std::max(q.max_relative_distance, std::abs(vg.value) / g / diagonal);
      gradients.push_back(vg.gradient);
    }
    if (m.vertex_patch[v] < 0 && !corners.count(v))
      for (std::size_t i = 1; i < gradients.size(); ++i)
        q.seam_gradient_angle = std::max(q.seam_gradient_angle, angle_degrees(gradients[0], gradients[i]));
  }

  q.worst_seam_ratio = seam_ratio(
      m, edge_triangles, diagonal,
      [&](std::size_t t) {
        const Triangle& tri = m.mesh.triangles[t];
        return Vec3((pos[tri[1]] - pos[tri[0]]).cross(pos[tri[2]] - pos[tri[0]]));
      },
      &q);
  q.surface_seam_ratio = seam_ratio(
      m, edge_triangles, diagonal,
      [&](std::size_t t) {
        const Triangle& tri = m.mesh.triangles[t];
        const Vec3 centroid = (pos[tri[0]] + pos[tri[1]] + pos[tri[2]]) / 3.0;
        return f[m.triangle_patch[t]]->value_gradient(centroid).gradient;
      },
      nullptr);
  return q;
}

}  // namespace isopatch
