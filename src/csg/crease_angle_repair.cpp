/// \file crease_angle_repair.cpp
/// Small angles along the pieces' boundaries repaired by constrained moves (crease_angle_repair.hpp).
#include "csg/crease_angle_repair.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <optional>
#include <set>
#include <string>

#include "core/triangle_angle.hpp"
#include "surface/curve_point.hpp"
#include "surface/project_point.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

namespace {

/// Sweeps over the vertices of small-angle triangles.
constexpr int kSweeps = 6;
/// Shares of the way to the neighbours' mean tried, largest first.
constexpr double kSteps[] = {1.0, 0.5, 0.25};

/// The smallest angle (degrees) of the triangles around v with v at `p`, or -1 when one of them turns
/// against the outward normal `n` of its faces there.
double fan_angle(const Mesh& mesh, const std::vector<std::uint32_t>& fan, std::uint32_t v, const Vec3& p,
                 const std::vector<Vec3>& normals) {
  double smallest = 180.0;
  for (const std::uint32_t t : fan) {
    Vec3 q[3];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t w = mesh.triangles[t][static_cast<std::size_t>(k)];
      q[k] = w == v ? p : mesh.positions[w];
    }
    const Vec3 n = (q[1] - q[0]).cross(q[2] - q[0]);
    Vec3 expected = Vec3::Zero();
    for (int k = 0; k < 3; ++k) expected += normals[mesh.triangles[t][static_cast<std::size_t>(k)]];
    if (!(n.dot(expected) > 0.0)) return -1.0;
    smallest = std::min(smallest, (smallest_angle(q[0], q[1], q[2])));
  }
  return smallest;
}

}  // namespace

AngleRepair repair_small_angles(Mesh& mesh, const std::vector<SurfacePtr>& faces, double floor_degrees,
                                double on_face, double tolerance, const std::vector<std::uint8_t>* held) {
  AngleRepair out;
  const std::size_t n = mesh.positions.size();
  if (held && held->size() != n)
    throw InputError("repair: " + std::to_string(held->size()) + " held flags for " + std::to_string(n) +
                     " vertices");
  std::vector<std::vector<std::uint32_t>> fan(n);
  std::vector<std::set<std::uint32_t>> neighbours(n);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[t][static_cast<std::size_t>(k)];
      fan[v].push_back(static_cast<std::uint32_t>(t));
      neighbours[v].insert(mesh.triangles[t][static_cast<std::size_t>((k + 1) % 3)]);
      neighbours[v].insert(mesh.triangles[t][static_cast<std::size_t>((k + 2) % 3)]);
    }
  const auto triangle_angle = [&](std::size_t t) {
    const Triangle& tr = mesh.triangles[t];
    return smallest_angle(mesh.positions[tr[0]], mesh.positions[tr[1]], mesh.positions[tr[2]]);
  };
  std::deque<Sampler> samplers;  // not movable: a deque builds them in place
  for (const SurfacePtr& f : faces) samplers.emplace_back(*f);
  // The faces each vertex lies on (indices into `faces`), found when first needed.
  std::vector<std::optional<std::vector<std::size_t>>> on(n);
  const auto faces_of = [&](std::uint32_t v) -> const std::vector<std::size_t>& {
    if (!on[v]) {
      on[v].emplace();
      for (std::size_t i = 0; i < faces.size(); ++i) {
        const ValueGradient g = samplers[i].value_gradient(mesh.positions[v]);
        if (std::abs(g.value) <= on_face * g.gradient.norm()) on[v]->push_back(i);
      }
    }
    return *on[v];
  };
  std::vector<Vec3> normals(n, Vec3::Zero());
  const auto normal_of = [&](std::uint32_t v) {
    Vec3 sum = Vec3::Zero();
    for (const std::size_t i : faces_of(v))
      sum += samplers[i].value_gradient(mesh.positions[v]).gradient.normalized();
    return sum;
  };
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    std::set<std::uint32_t> candidates;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (triangle_angle(t) < floor_degrees)
        for (const std::uint32_t v : mesh.triangles[t]) candidates.insert(v);
    if (candidates.empty()) break;
    std::size_t moved = 0;
    for (const std::uint32_t v : candidates) {
      if (held && (*held)[v]) continue;  // a seam vertex of a block: the block across has it here
      const std::vector<std::size_t>& on_v = faces_of(v);
      if (on_v.empty() || on_v.size() > 2) continue;  // a corner (or a vertex off every face) stays
      for (const std::uint32_t w : neighbours[v]) normals[w] = normal_of(w);
      normals[v] = normal_of(v);
      const Vec3 p = mesh.positions[v];
      const double before = fan_angle(mesh, fan[v], v, p, normals);
      Vec3 mean = Vec3::Zero();
      double edge = 0.0;
      for (const std::uint32_t w : neighbours[v]) {
        mean += mesh.positions[w];
        edge += (mesh.positions[w] - p).norm();
      }
      mean /= static_cast<double>(neighbours[v].size());
      edge /= static_cast<double>(neighbours[v].size());
      // Candidates: part of the way to the neighbours' mean, and short steps in eight directions of the
      // tangent plane (along the crease: both ways); the best that raises the fan's smallest angle wins.
      const Vec3 normal = normals[v].normalized();
      const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
      std::vector<Vec3> targets;
      for (const double step : kSteps) targets.push_back(p + step * (mean - p));
      for (const double size : {0.05, 0.15})
        for (int k = 0; k < 8; ++k) {
          const double a = k * std::numbers::pi / 4.0;
          targets.push_back(p + size * edge * (std::cos(a) * e1 + std::sin(a) * e2));
        }
      double best = before + 1e-9;
      std::optional<Vec3> best_q;
      for (Vec3 target : targets) {
        std::optional<Vec3> q;
        if (on_v.size() == 1) {
          if (project_to_surface(samplers[on_v[0]], target, tolerance, edge)) q = target;
        } else {
          // Along the crease only, then back onto both functions.
          const Surface& a = *faces[on_v[0]];
          const Surface& b = *faces[on_v[1]];
          const Vec3 t = a.value_gradient(p).gradient.cross(b.value_gradient(p).gradient).normalized();
          target = p + (target - p).dot(t) * t;
          CurvePointParams cp;
          cp.tolerance = tolerance;
          cp.max_step = (target - p).norm() + tolerance;
          cp.max_travel = 2.0 * cp.max_step;
          q = settle_on_curve(a, b, target, cp);
        }
        if (!q) continue;
        const double after = fan_angle(mesh, fan[v], v, *q, normals);
        if (after > best) {
          best = after;
          best_q = q;
        }
      }
      if (best_q) {
        mesh.positions[v] = *best_q;
        ++moved;
      }
    }
    out.moved += moved;
    if (moved == 0) break;
  }
  return out;
}

}  // namespace isopatch
