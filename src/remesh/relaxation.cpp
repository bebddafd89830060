// Tangential relaxation of the surface-bound clean-up, see relaxation.hpp.
#include "remesh/relaxation.hpp"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "remesh/box_boundary.hpp"
#include "surface/project_point.hpp"

namespace isopatch::cleanup {

void relax(RemeshRun& run, int rounds) {
  std::vector<std::uint32_t> all;
  for (std::uint32_t v = 0; v < run.mesh.vertex_slots(); ++v)
    if (run.mesh.alive(v)) all.push_back(v);
  relax(run, all, rounds);
}

void relax(RemeshRun& run, const std::vector<std::uint32_t>& vertices, int rounds) {
  const std::vector<std::vector<std::uint32_t>> classes = run.mesh.independent_classes(vertices);
  std::atomic<std::size_t> rejected{0};
  for (int round = 0; round < rounds; ++round) {
    run.check_cancel();
    for (const std::vector<std::uint32_t>& members : classes)
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, members.size(), 256), [&](const auto& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i)
          if (!relax_vertex(run, members[i])) rejected.fetch_add(1, std::memory_order_relaxed);
      });
  }
  run.stats.rejected_moves += rejected.load();
}

bool relax_vertex(RemeshRun& run, std::uint32_t v) {
  if (!run.mesh.alive(v)) return true;
  if (run.mesh.locked[v])
    return (run.slide_axis(v) < 0 && run.slide_plane(v) < 0) || relax_along_box_face(run, v);
  Vec3 centroid = Vec3::Zero();
  double area = 0.0;
  for (std::uint32_t t : run.mesh.incident[v]) {
    const Triangle& tri = run.mesh.triangles[t];
    const Vec3& p0 = run.mesh.positions[tri[0]];
    const Vec3& p1 = run.mesh.positions[tri[1]];
    const Vec3& p2 = run.mesh.positions[tri[2]];
    const double a = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    centroid += a * (p0 + p1 + p2) / 3.0;
    area += a;
  }
  if (!(area > 0.0)) return true;
  centroid /= area;
  const Vec3& p = run.mesh.positions[v];
  const Vec3& n = run.mesh.normals[v];
  Vec3 move = centroid - p;
  move -= n * n.dot(move);
  Vec3 q = p + move;
  Vec3 nq;
  if (!run.project(q, nq, std::max(move.norm(), run.sizes.at(v)))) return false;
  for (std::uint32_t t : run.mesh.incident[v])
    if (!run.triangle_ok_with(t, v, q, nq)) return false;
  run.mesh.positions[v] = q;
  run.mesh.normals[v] = nq;
  return true;
}

bool relax_along_box_face(RemeshRun& run, std::uint32_t v) {
  const std::vector<std::uint32_t> ends = run.mesh.boundary_neighbours(v);
  if (ends.size() != 2) return true;
  const int axis = run.slide_axis(v);
  const Vec3& p = run.mesh.positions[v];
  Vec3 q = 0.5 * (run.mesh.positions[ends[0]] + run.mesh.positions[ends[1]]);
  const double step = std::max((q - p).norm(), run.sizes.at(v));
  Vec3 gradient;
  if (axis < 0) {
    const auto k = static_cast<std::size_t>(run.slide_plane(v));
    const bool moved =
        project_onto_cut_plane(run.f, q, run.planes, k, run.tolerance, run.plane_margin(), step, &gradient);
    return moved && run.in_box(q) && !on_box_face(run.settings.box, q) &&
           move_boundary_vertex(run, v, q, gradient);
  }
  q[axis] = p[axis];
  if (!project_to_surface_in_plane(run.f, q, axis, run.tolerance, step, &gradient) || !run.in_box(q))
    return false;
  for (int k = 0; k < 3; ++k)
    if (k != axis && (q[k] == run.settings.box->lo[k] || q[k] == run.settings.box->hi[k])) return true;
  return move_boundary_vertex(run, v, q, gradient);
}

bool move_boundary_vertex(RemeshRun& run, std::uint32_t v, const Vec3& q, const Vec3& gradient) {
  const Vec3 n = gradient.normalized();
  for (std::uint32_t t : run.mesh.incident[v])
    if (!run.triangle_ok_with(t, v, q, n)) return false;
  run.mesh.positions[v] = q;
  run.mesh.normals[v] = n;
  return true;
}

}  // namespace isopatch::cleanup
