// Jacobi relaxation of a refined mesh on f = 0 (lattice_relaxation.hpp).
#include "refine/lattice_relaxation.hpp"

#include <algorithm>
#include <array>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "core/triangle_angle.hpp"
#include "remesh/remesh_thresholds.hpp"

namespace isopatch::refine {
namespace {

/// Vertices per task and per batch of evaluations.
constexpr std::size_t kChunk = 2048;

Vec3 as_vec3(const Eigen::Vector3f& v) {
  return v.cast<double>();
}

}  // namespace

bool faces_the_surface(const Vec3& a, const Vec3& b, const Vec3& c,
                       const std::array<Eigen::Vector3f, 3>& corner_normals) {
  const Vec3 normal = (b - a).cross(c - a);
  const double length = normal.norm();
  if (!(length > 0.0)) return false;
  for (const Eigen::Vector3f& n : corner_normals)
    if (!(normal.dot(as_vec3(n)) > remesh_thresholds::kMinNormalDot * length)) return false;
  return true;
}

bool faces_the_surface(const std::vector<Vec3>& positions, const std::vector<Eigen::Vector3f>& normals,
                       const Triangle& t) {
  return faces_the_surface(positions[t[0]], positions[t[1]], positions[t[2]],
                           {normals[t[0]], normals[t[1]], normals[t[2]]});
}

double smallest_angle_degrees(const Mesh& mesh, const Triangle& t) {
  return smallest_angle(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
}

double smallest_angle_degrees(const Mesh& mesh) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, mesh.triangles.size(), kChunk), 180.0,
      [&](const tbb::blocked_range<std::size_t>& r, double least) {
        for (std::size_t t = r.begin(); t != r.end(); ++t)
          least = std::min(least, smallest_angle_degrees(mesh, mesh.triangles[t]));
        return least;
      },
      [](double a, double b) { return std::min(a, b); });
}

LatticeRelaxation::LatticeRelaxation(Mesh& mesh, std::vector<Eigen::Vector3f>& normals,
                                     const std::vector<Motion>& motion, const LatticeLayout& layout,
                                     const BaseEdges& edges, const std::vector<int>& edge_plane,
                                     std::span<const Sampler* const> functions,
                                     const std::vector<std::uint32_t>& vertex_function,
                                     const BoundaryPlanes& planes, const NewtonLimits& limits,
                                     std::size_t block)
    : mesh_(mesh),
      normals_(normals),
      motion_(motion),
      layout_(layout),
      edges_(edges),
      edge_plane_(edge_plane),
      functions_(functions),
      vertex_function_(vertex_function),
      planes_(planes),
      limits_(limits),
      block_(std::max<std::size_t>(block, 1)),
      rings_(mesh.vertex_count(), mesh.triangles) {
  // The triangles with a corner in each block, ascending, each once per block: two passes.
  const std::size_t blocks = (mesh.vertex_count() + block_ - 1) / block_;
  const auto blocks_of = [&](const Triangle& t, std::array<std::size_t, 3>& out) {
    std::size_t count = 0;
    for (const std::uint32_t v : t) {
      const std::size_t b = v / block_;
      if (std::find(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(count), b) ==
          out.begin() + static_cast<std::ptrdiff_t>(count))
        out[count++] = b;
    }
    return count;
  };
  block_offsets_.assign(blocks + 1, 0);
  std::array<std::size_t, 3> in{};
  for (const Triangle& t : mesh.triangles)
    for (std::size_t k = 0, n = blocks_of(t, in); k < n; ++k) ++block_offsets_[in[k] + 1];
  for (std::size_t b = 0; b < blocks; ++b) block_offsets_[b + 1] += block_offsets_[b];
  block_triangles_.resize(block_offsets_.back());
  std::vector<std::uint32_t> next(block_offsets_.begin(), block_offsets_.end() - 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::size_t k = 0, n = blocks_of(mesh.triangles[t], in); k < n; ++k)
      block_triangles_[next[in[k]]++] = static_cast<std::uint32_t>(t);
}

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
  std::size_t undone = 0;
  for (std::size_t begin = 0; begin < mesh_.vertex_count(); begin += block_)
    undone += sweep_block(begin, std::min(mesh_.vertex_count(), begin + block_), subset);
  return undone;
}

std::size_t LatticeRelaxation::sweep_block(std::size_t begin, std::size_t end,
                                           const std::vector<std::uint8_t>* subset) {
  next_.assign(mesh_.positions.begin() + static_cast<std::ptrdiff_t>(begin),
               mesh_.positions.begin() + static_cast<std::ptrdiff_t>(end));
  next_normals_.assign(normals_.begin() + static_cast<std::ptrdiff_t>(begin),
                       normals_.begin() + static_cast<std::ptrdiff_t>(end));
  moved_.assign(end - begin, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, kChunk),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      std::vector<NewtonPoint> points;
                      std::vector<std::uint32_t> ids;
                      for (std::size_t v = r.begin(); v != r.end(); ++v) {
                        if (subset && !(*subset)[v]) continue;
                        NewtonPoint p;
                        if (!target(static_cast<std::uint32_t>(v), p.position, p.plane)) continue;
                        p.expected_normal = as_vec3(normals_[v]);
                        p.piece = vertex_function_.empty() ? 0 : vertex_function_[v];
                        // A relaxation move is a fraction of an edge: a landing further away than the move
                        // itself went somewhere else.
                        p.max_move = 2.0 * (p.position - mesh_.positions[v]).norm() + limits_.tolerance;
                        points.push_back(p);
                        ids.push_back(static_cast<std::uint32_t>(v));
                      }
                      land_on_surface(functions_, planes_, points, limits_);
                      for (std::size_t i = 0; i < points.size(); ++i) {
                        if (points[i].landing != Landing::Ok) continue;
                        next_[ids[i] - begin] = points[i].position;
                        next_normals_[ids[i] - begin] = points[i].normal.cast<float>();
                        moved_[ids[i] - begin] = 1;
                      }
                    });
  const auto moved = [&](std::uint32_t v) { return v >= begin && v < end && moved_[v - begin]; };
  const auto position = [&](std::uint32_t v) -> const Vec3& {
    return moved(v) ? next_[v - begin] : mesh_.positions[v];
  };
  const auto normal = [&](std::uint32_t v) -> const Eigen::Vector3f& {
    return moved(v) ? next_normals_[v - begin] : normals_[v];
  };
  // Undo the moves that leave a triangle turned away from the surface, until none does (the positions
  // before the sweep are valid, so this ends).
  // Only the triangles with a corner in the block can have a moved corner (before, every triangle of
  // the mesh was tested for each block: a time quadratic in the mesh).
  const std::size_t block_index = begin / block_;
  const std::span<const std::uint32_t> triangles(block_triangles_.data() + block_offsets_[block_index],
                                                 block_triangles_.data() + block_offsets_[block_index + 1]);
  std::size_t undone = 0;
  for (bool changed = true; changed;) {
    changed = false;
    invalid_.assign(triangles.size(), 0);
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, triangles.size(), kChunk),
        [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t k = r.begin(); k != r.end(); ++k) {
            const Triangle& tri = mesh_.triangles[triangles[k]];
            if (!moved(tri[0]) && !moved(tri[1]) && !moved(tri[2])) continue;
            const Vec3 &a = position(tri[0]), &b = position(tri[1]), &c = position(tri[2]);
            bool valid = faces_the_surface(a, b, c, {normal(tri[0]), normal(tri[1]), normal(tri[2])});
            if (valid && angle_guard_ > 0.0) {
              // A move may not close a triangle under the guard angle further.
              const double now = smallest_angle(a, b, c);
              valid = now >= angle_guard_ ||
                      now >= smallest_angle(mesh_.positions[tri[0]], mesh_.positions[tri[1]],
                                            mesh_.positions[tri[2]]);
            }
            invalid_[k] = valid ? 0 : 1;
          }
        });
    for (std::size_t k = 0; k < invalid_.size(); ++k) {
      if (!invalid_[k]) continue;
      for (std::uint32_t v : mesh_.triangles[triangles[k]]) {
        if (!moved(v)) continue;
        moved_[v - begin] = 0;
        ++undone;
        changed = true;
      }
    }
  }
  for (std::size_t v = begin; v < end; ++v)
    if (moved_[v - begin]) {
      mesh_.positions[v] = next_[v - begin];
      normals_[v] = next_normals_[v - begin];
    }
  return undone;
}

}  // namespace isopatch::refine
