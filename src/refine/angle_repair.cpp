// Pattern search on the smallest angle around a vertex (angle_repair.hpp).
#include "refine/angle_repair.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include "core/triangle_angle.hpp"

namespace isopatch::refine {
namespace {

/// Directions tried around a vertex and step lengths as shares of its mean edge: the 24 candidates are
/// landed in one batch and the best is kept.
constexpr int kDirections = 8;
constexpr std::array<double, 5> kSteps = {0.3, 0.15, 0.07, 0.03, 0.01};

struct Fan {
  std::vector<std::uint32_t> triangles;
};

/// The smallest angle of the triangles `fan` when vertex v is at `p` with unit normal `n`, or -1 when
/// one of them would turn away from the surface.
double fan_angle(const Mesh& mesh, const std::vector<Eigen::Vector3f>& normals, const Fan& fan,
                 std::uint32_t v, const Vec3& p, const Eigen::Vector3f& n) {
  double least = 180.0;
  for (const std::uint32_t t : fan.triangles) {
    std::array<Vec3, 3> corner;
    std::array<Eigen::Vector3f, 3> normal;
    for (std::size_t i = 0; i < 3; ++i) {
      const std::uint32_t u = mesh.triangles[t][i];
      corner[i] = u == v ? p : mesh.positions[u];
      normal[i] = u == v ? n : normals[u];
    }
    if (!faces_the_surface(corner[0], corner[1], corner[2], normal)) return -1.0;
    least = std::min(least, smallest_angle(corner[0], corner[1], corner[2]));
  }
  return least;
}

}  // namespace

std::size_t repair_small_angles(Mesh& mesh, std::vector<Eigen::Vector3f>& normals, const AngleRepairInput& in,
                                double floor, int rounds) {
  // The free vertices of the triangles under the floor, with their fans: two parallel scans of the
  // triangles, each thread collecting its own list; the lists sorted, so the fans are the same for any
  // thread count.
  constexpr std::size_t kGrain = 8192;
  tbb::combinable<std::vector<std::uint32_t>> seeds;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, mesh.triangles.size(), kGrain),
      [&](const tbb::blocked_range<std::size_t>& r) {
        auto& local = seeds.local();
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          const Triangle& tri = mesh.triangles[t];
          if (smallest_angle(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]) < floor)
            for (const std::uint32_t v : tri)
              if (in.motion[v] == Motion::Free) local.push_back(v);
        }
      });
  std::vector<std::uint32_t> vertices;
  seeds.combine_each(
      [&](const std::vector<std::uint32_t>& l) { vertices.insert(vertices.end(), l.begin(), l.end()); });
  if (vertices.empty()) return 0;
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  std::vector<std::uint8_t> wanted(mesh.vertex_count(), 0);
  for (const std::uint32_t v : vertices) wanted[v] = 1;
  tbb::combinable<std::vector<std::pair<std::uint32_t, std::uint32_t>>> corners;  // (vertex, triangle)
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.triangles.size(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      auto& local = corners.local();
                      for (std::size_t t = r.begin(); t != r.end(); ++t)
                        for (const std::uint32_t v : mesh.triangles[t])
                          if (wanted[v]) local.emplace_back(v, static_cast<std::uint32_t>(t));
                    });
  std::vector<std::pair<std::uint32_t, std::uint32_t>> incident;
  corners.combine_each([&](const auto& l) { incident.insert(incident.end(), l.begin(), l.end()); });
  std::sort(incident.begin(), incident.end());
  std::map<std::uint32_t, Fan> fans;
  for (const auto& [v, t] : incident) fans[v].triangles.push_back(t);

  std::size_t moves = 0;
  std::vector<NewtonPoint> candidates;
  for (int round = 0; round < rounds; ++round) {
    std::size_t moved = 0;
    for (const auto& [v, fan] : fans) {
      const Vec3 p = mesh.positions[v];
      const double now = fan_angle(mesh, normals, fan, v, p, normals[v]);
      if (now >= floor || now < 0.0) continue;
      double edge = 0.0;
      for (const std::uint32_t t : fan.triangles)
        for (const std::uint32_t u : mesh.triangles[t])
          if (u != v) edge += (mesh.positions[u] - p).norm();
      edge /= static_cast<double>(2 * fan.triangles.size());
      const Vec3 n = normals[v].cast<double>().normalized();
      const Vec3 t1 = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
      const Vec3 t2 = n.cross(t1);
      candidates.clear();
      for (const double share : kSteps)
        for (int d = 0; d < kDirections; ++d) {
          const double angle = 2.0 * std::numbers::pi * d / kDirections;
          NewtonPoint c;
          const double step = share * edge;
          c.position = p + step * (std::cos(angle) * t1 + std::sin(angle) * t2);
          c.expected_normal = n;
          c.max_move = 2.0 * step + in.limits.tolerance;
          c.piece = in.vertex_function.empty() ? 0 : in.vertex_function[v];
          candidates.push_back(c);
        }
      land_on_surface(in.functions, in.planes, candidates, in.limits);
      double best = now;
      const NewtonPoint* chosen = nullptr;
      for (const NewtonPoint& c : candidates) {
        if (c.landing != Landing::Ok) continue;
        const double a = fan_angle(mesh, normals, fan, v, c.position, c.normal.cast<float>());
        if (a > best) {
          best = a;
          chosen = &c;
        }
      }
      if (!chosen) continue;
      mesh.positions[v] = chosen->position;
      normals[v] = chosen->normal.cast<float>();
      ++moved;
    }
    moves += moved;
    if (moved == 0) break;
  }
  return moves;
}

}  // namespace isopatch::refine
