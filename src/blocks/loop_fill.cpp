// A loop with no mesh beside it filled by triangles (loop_fill.hpp).
#include "blocks/loop_fill.hpp"

#include <isopatch/error.hpp>

#include "remesh/remesh_thresholds.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace isopatch::blocks {
namespace {

/// Loops of more points than this are filled by a fan (the triangulation costs n^3).
constexpr std::size_t kLargestTriangulated = 160;

/// p moved onto f = 0 along grad f (a few Newton steps).
Vec3 onto_surface(const Surface& surface, Vec3 p) {
  for (int it = 0; it < 20; ++it) {
    const ValueGradient vg = surface.value_gradient(p);
    const double g2 = vg.gradient.squaredNorm();
    if (!std::isfinite(vg.value) || !std::isfinite(g2))
      throw EvaluationError("f is not finite near a tile's cut");
    if (g2 == 0.0) break;
    const Vec3 step = (vg.value / g2) * vg.gradient;
    p -= step;
    if (step.norm() < 1e-15 * (1.0 + p.norm())) break;
  }
  return p;
}

double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto angle = [](const Vec3& p, const Vec3& q, const Vec3& r) {
    const Vec3 u = q - p, v = r - p;
    return std::atan2(u.cross(v).norm(), u.dot(v));
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

void fan(const Surface& surface, std::vector<std::uint32_t>& loop, Mesh& out) {
  Vec3 centre = Vec3::Zero();
  for (const std::uint32_t v : loop) centre += out.positions[v];
  centre = onto_surface(surface, centre / static_cast<double>(loop.size()));
  Vec3 area = Vec3::Zero();
  for (std::size_t j = 0; j < loop.size(); ++j)
    area += (out.positions[loop[j]] - centre).cross(out.positions[loop[(j + 1) % loop.size()]] - centre);
  if (area.dot(surface.value_gradient(centre).gradient) < 0.0) std::reverse(loop.begin(), loop.end());
  const auto c = static_cast<std::uint32_t>(out.positions.size());
  out.positions.push_back(centre);
  for (std::size_t j = 0; j < loop.size(); ++j)
    out.triangles.push_back({loop[j], loop[(j + 1) % loop.size()], c});
}

}  // namespace

bool faces_along(const Vec3& a, const Vec3& b, const Vec3& c, const std::array<Vec3, 3>& gradients) {
  const Vec3 normal = (b - a).cross(c - a);
  const double length = normal.norm();
  if (!(length > 0.0)) return false;
  for (const Vec3& g : gradients)
    if (!(normal.dot(g) > remesh_thresholds::kMinNormalDot * length * g.norm())) return false;
  return true;
}

bool fill_loop(const Surface& surface, std::vector<std::uint32_t>& loop, Mesh& out) {
  const auto& P = out.positions;
  const std::size_t n = loop.size();
  // The loop turned so that it runs counter-clockwise about grad f (Newell's normal against the sum of
  // the gradients at its points).
  Vec3 newell = Vec3::Zero(), g = Vec3::Zero();
  std::vector<Vec3> gradient(n);
  for (std::size_t j = 0; j < n; ++j) {
    newell += P[loop[j]].cross(P[loop[(j + 1) % n]]);
    gradient[j] = surface.value_gradient(P[loop[j]]).gradient;
    g += gradient[j];
  }
  if (!std::isfinite(g.squaredNorm())) throw EvaluationError("f is not finite on a tile's cut");
  if (newell.dot(g) < 0.0) {
    std::reverse(loop.begin(), loop.end());
    std::reverse(gradient.begin(), gradient.end());
  }
  if (n > kLargestTriangulated) {
    fan(surface, loop, out);
    return false;
  }
  // The triangulation of the polygon that makes the smallest angle largest among those whose every
  // triangle faces along grad f (dynamic programming over sub-polygons i..j, after Liepa 2003, "Filling
  // holes in meshes", with this weight). best[i][j]: that smallest angle, -1 when none faces right.
  const auto quality = [&](std::size_t i, std::size_t k, std::size_t j) {
    const Vec3 &a = P[loop[i]], &b = P[loop[k]], &c = P[loop[j]];
    if (!faces_along(a, b, c, {gradient[i], gradient[k], gradient[j]})) return -1.0;
    return smallest_angle(a, b, c);
  };
  std::vector<double> best(n * n, 2.0 * M_PI);
  std::vector<std::size_t> split(n * n, 0);
  for (std::size_t length = 2; length < n; ++length)
    for (std::size_t i = 0; i + length < n; ++i) {
      const std::size_t j = i + length;
      double value = -2.0;
      for (std::size_t k = i + 1; k < j; ++k) {
        const double v = std::min({best[i * n + k], best[k * n + j], quality(i, k, j)});
        if (v > value) {
          value = v;
          split[i * n + j] = k;
        }
      }
      best[i * n + j] = value;
    }
  if (best[n - 1] < 0.0) {  // no triangulation of the loop faces along grad f everywhere
    fan(surface, loop, out);
    return false;
  }
  std::vector<std::array<std::size_t, 2>> pending{{0, n - 1}};
  while (!pending.empty()) {
    const auto [i, j] = pending.back();
    pending.pop_back();
    if (j - i < 2) continue;
    const std::size_t k = split[i * n + j];
    out.triangles.push_back({loop[i], loop[k], loop[j]});
    pending.push_back({i, k});
    pending.push_back({k, j});
  }
  return true;
}

}  // namespace isopatch::blocks
