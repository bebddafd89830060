// Jacobi relaxation of a refined mesh on f = 0 (lattice_relaxation.hpp).
#include "refine/lattice_relaxation.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "remesh/remesh_thresholds.hpp"
#include "remesh/triangle_angle.hpp"

namespace isopatch::refine {
namespace {

/// Vertices per task and per batch of evaluations.
constexpr std::size_t kChunk = 2048;

Vec3 as_vec3(const Eigen::Vector3f& v) {
  return v.cast<double>();
}

}  // namespace

bool faces_the_surface(const std::vector<Vec3>& positions, const std::vector<Eigen::Vector3f>& normals,
                       const Triangle& t) {
  const Vec3 normal = (positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]);
  const double length = normal.norm();
  if (!(length > 0.0)) return false;
  for (const std::uint32_t v : t)
    if (!(normal.dot(as_vec3(normals[v])) > remesh_thresholds::kMinNormalDot * length)) return false;
  return true;
}

double smallest_angle_degrees(const Mesh& mesh, const Triangle& t) {
  return smallest_angle(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
}

LatticeRelaxation::LatticeRelaxation(Mesh& mesh, std::vector<Eigen::Vector3f>& normals,
                                     const std::vector<Motion>& motion, const LatticeLayout& layout,
                                     const BaseEdges& edges, const std::vector<int>& edge_plane,
                                     const Sampler& f, const BoundaryPlanes& planes,
                                     const NewtonLimits& limits)
    : mesh_(mesh),
      normals_(normals),
      motion_(motion),
      layout_(layout),
      edges_(edges),
      edge_plane_(edge_plane),
      f_(f),
      planes_(planes),
      limits_(limits),
      rings_(mesh.vertex_count(), mesh.triangles) {}

bool LatticeRelaxation::target(std::uint32_t v, Vec3& to, int& plane) const {
  const Vec3& p = mesh_.positions[v];
  if (motion_[v] == Motion::Locked) return false;
  if (motion_[v] == Motion::Slides) {
    // An edge point of a boundary edge: its neighbours on the curve are the points before and after
    // it on the same base edge (the edge's ends at either extreme).
    const std::size_t index = v - layout_.base_vertices();
    const int k = layout_.level();
    const auto e = static_cast<std::uint32_t>(index / static_cast<std::size_t>(k - 1));
    const int j = static_cast<int>(index % static_cast<std::size_t>(k - 1)) + 1;
    const auto at = [&](int i) -> const Vec3& {
      if (i == 0) return mesh_.positions[edges_.ends[e][0]];
      if (i == k) return mesh_.positions[edges_.ends[e][1]];
      return mesh_.positions[layout_.edge_point(e, i)];
    };
    const Vec3 middle = 0.5 * (at(j - 1) + at(j + 1));
    to = p + kRelaxationStep * (middle - p);
    plane = edge_plane_[e];
    return true;
  }
  const auto ring = rings_.of(v);
  if (ring.empty()) return false;
  Vec3 centroid = Vec3::Zero();
  for (std::uint32_t u : ring) centroid += mesh_.positions[u];
  centroid /= static_cast<double>(ring.size());
  const Vec3 n = as_vec3(normals_[v]);
  Vec3 d = centroid - p;
  d -= d.dot(n) * n;
  to = p + kRelaxationStep * d;
  plane = -1;
  return true;
}

std::size_t LatticeRelaxation::sweep(const std::vector<std::uint8_t>* subset) {
  const std::size_t n = mesh_.vertex_count();
  next_ = mesh_.positions;
  next_normals_ = normals_;
  moved_.assign(n, 0);
  std::vector<Vec3>& next = next_;
  std::vector<Eigen::Vector3f>& next_normals = next_normals_;
  std::vector<std::uint8_t>& moved = moved_;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kChunk),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      std::vector<NewtonPoint> points;
                      std::vector<std::uint32_t> ids;
                      for (std::size_t v = r.begin(); v != r.end(); ++v) {
                        if (subset && !(*subset)[v]) continue;
                        NewtonPoint p;
                        if (!target(static_cast<std::uint32_t>(v), p.position, p.plane)) continue;
                        p.expected_normal = as_vec3(normals_[v]);
                        // A relaxation move is a fraction of an edge: a landing further away than the move
                        // itself went somewhere else.
                        p.max_move = 2.0 * (p.position - mesh_.positions[v]).norm() + limits_.tolerance;
                        points.push_back(p);
                        ids.push_back(static_cast<std::uint32_t>(v));
                      }
                      land_on_surface(f_, planes_, points, limits_);
                      for (std::size_t i = 0; i < points.size(); ++i) {
                        if (points[i].landing != Landing::Ok) continue;
                        next[ids[i]] = points[i].position;
                        next_normals[ids[i]] = points[i].normal.cast<float>();
                        moved[ids[i]] = 1;
                      }
                    });
  // Undo the moves that leave a triangle turned away from the surface, until none does (the positions
  // before the sweep are valid, so this ends).
  std::size_t undone = 0;
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<std::uint8_t>& invalid = invalid_;
    invalid.assign(mesh_.triangles.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh_.triangles.size(), kChunk),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t t = r.begin(); t != r.end(); ++t) {
                          const Triangle& tri = mesh_.triangles[t];
                          if (!moved[tri[0]] && !moved[tri[1]] && !moved[tri[2]]) continue;
                          invalid[t] = faces_the_surface(next, next_normals, tri) ? 0 : 1;
                        }
                      });
    for (std::size_t t = 0; t < invalid.size(); ++t) {
      if (!invalid[t]) continue;
      for (std::uint32_t v : mesh_.triangles[t]) {
        if (!moved[v]) continue;
        next[v] = mesh_.positions[v];
        next_normals[v] = normals_[v];
        moved[v] = 0;
        ++undone;
        changed = true;
      }
    }
  }
  mesh_.positions.swap(next);
  normals_.swap(next_normals);
  return undone;
}

}  // namespace isopatch::refine
