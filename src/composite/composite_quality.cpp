/// \file composite_quality.cpp
/// Quality of a composite's mesh by patch and across seams (composite_quality.hpp).
#include "composite/composite_quality.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "surface/sampler.hpp"

namespace isopatch {

namespace {

double angle_degrees(const Vec3& a, const Vec3& b) {
  const double c = a.normalized().dot(b.normalized());
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
}

double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return std::min({angle_degrees(b - a, c - a), angle_degrees(a - b, c - b), angle_degrees(a - c, b - c)});
}

}  // namespace

CompositeQuality measure_composite_mesh(const Composite& composite, const CompositeMesh& m) {
  CompositeQuality q;
  const auto& pos = m.mesh.positions;
  const std::size_t nv = pos.size();
  std::vector<std::set<std::uint32_t>> neighbours(nv);
  std::vector<std::set<std::uint32_t>> vertex_patches(nv);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> edge_triangles;
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
  std::set<std::uint32_t> corners;
  for (const ConicArc& a : composite.curves)
    for (std::uint32_t v = 0; v < nv && m.vertex_patch[v] < 0; ++v)
      if (pos[v] == a.start || pos[v] == a.end) corners.insert(v);
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

  double seam_sum = 0.0, patch_sum = 0.0;
  std::vector<double> patch_jump(composite.patches.size(), 0.0);
  std::vector<std::size_t> patch_count(composite.patches.size(), 0);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<double, std::size_t>> seam_jump;
  for (const auto& [edge, triangles] : edge_triangles) {
    if (triangles.size() != 2) continue;
    const auto normal = [&](std::size_t t) {
      const Triangle& tri = m.mesh.triangles[t];
      return Vec3((pos[tri[1]] - pos[tri[0]]).cross(pos[tri[2]] - pos[tri[0]]));
    };
    const double length = (pos[edge.first] - pos[edge.second]).norm();
    if (!(length > 0.0)) continue;
    const double jump = angle_degrees(normal(triangles[0]), normal(triangles[1])) / length;
    const std::uint32_t a = m.triangle_patch[triangles[0]], b = m.triangle_patch[triangles[1]];
    if (a != b) {
      seam_sum += jump;
      ++q.seam_edges;
      auto& [sum, count] = seam_jump[{std::min(a, b), std::max(a, b)}];
      sum += jump;
      ++count;
    } else {
      patch_sum += jump;
      ++q.patch_edges;
      patch_jump[a] += jump;
      ++patch_count[a];
    }
  }
  const double floor = 1.0 / diagonal;
  for (const auto& [pair, jumps] : seam_jump) {
    const auto mean = [&](std::uint32_t p) {
      return patch_count[p] ? patch_jump[p] / static_cast<double>(patch_count[p]) : 0.0;
    };
    const double own = std::max({mean(pair.first), mean(pair.second), floor});
    q.worst_seam_ratio = std::max(q.worst_seam_ratio, jumps.first / static_cast<double>(jumps.second) / own);
  }
  q.seam_normal_jump = q.seam_edges ? seam_sum / static_cast<double>(q.seam_edges) : 0.0;
  q.patch_normal_jump = q.patch_edges ? patch_sum / static_cast<double>(q.patch_edges) : 0.0;
  return q;
}

}  // namespace isopatch
