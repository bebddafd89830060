/// \file ray_march.cpp
/// The one ray march (ray_march.hpp) and the curved bounds it may respect (march_region.hpp).
#include "projection/ray_march.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "surface/bracketed_root.hpp"

namespace isopatch {

double CurvedBounds::depth(const Vec3& x) const {
  double depth = std::numeric_limits<double>::infinity();
  for (const SurfacePtr& b : bounds_) {
    const ValueGradient vg = b->value_gradient(x);
    if (!std::isfinite(vg.value)) throw_not_finite("a bounding function", vg.value, x);
    if (!vg.gradient.allFinite())
      throw_not_finite("the gradient of a bounding function", vg.gradient.norm(), x);
    const double g = vg.gradient.norm();
    const double d = g > 0.0 ? vg.value / g
                             : (vg.value >= 0.0 ? std::numeric_limits<double>::infinity()
                                                : -std::numeric_limits<double>::infinity());
    depth = std::min(depth, d);
  }
  return depth;
}

double exit_distance(const Vec3& p, const Vec3& d, const Box& box) {
  double t = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (d[a] > 0.0)
      t = std::min(t, (box.hi[a] - p[a]) / d[a]);
    else if (d[a] < 0.0)
      t = std::min(t, (box.lo[a] - p[a]) / d[a]);
  }
  return std::max(t, 0.0);
}

namespace {

/// One ray of march_rays on its way: marching in fixed steps, then refining the bracket.
struct MarchingRay {
  Vec3 start, d;
  double t_max = 0.0, step = 0.0, t_a = 0.0, f_a = 0.0, t_query = 0.0;
  int i = 1;
  bool start_positive = false;
  bool was_inside = false;  ///< within the curved bounds at some point so far
  std::optional<BracketedRoot> root;
};

}  // namespace

void march_rays(const Sampler& f, std::span<const RayStart> rays, const Box& region,
                const RayMarchSettings& settings, std::vector<std::optional<RayHit>>& out) {
  march_rays(f, rays, MarchRegion::cell(region), settings, out);
}

void march_rays(const Sampler& f, std::span<const RayStart> rays, const MarchRegion& region,
                const RayMarchSettings& settings, std::vector<std::optional<RayHit>>& out) {
  out.assign(rays.size(), std::nullopt);
  const double scale = region.scale;
  const Box grown{region.box.lo - Vec3::Constant(settings.exit_margin * scale),
                  region.box.hi + Vec3::Constant(settings.exit_margin * scale)};
  const CurvedBounds* curved = region.curved;
  const auto hit_at = [&](const Vec3& x, const Vec3& d, double t) -> std::optional<RayHit> {
    if (!region.admits(x)) return std::nullopt;
    return RayHit{x, d, t};
  };
  std::vector<MarchingRay> state(rays.size());
  std::vector<std::size_t> going;  // indices of the rays still marching or refining
  // The same set-up as march_to_surface, ray by ray.
  for (std::size_t r = 0; r < rays.size(); ++r) {
    const RayStart& ray = rays[r];
    const double norm = ray.direction.norm();
    if (!(norm > 0.0)) continue;
    MarchingRay& m = state[r];
    m.start = ray.start;
    m.d = (ray.f_start < 0.0 ? 1.0 : -1.0) * ray.direction / norm;
    if (ray.f_start == 0.0) {
      out[r] = hit_at(ray.start, m.d, 0.0);
      continue;
    }
    m.t_max = std::min(exit_distance(ray.start, m.d, grown), region.reach);
    m.was_inside = curved && curved->inside(ray.start);
    if (!(m.t_max > 0.0)) continue;
    m.step = m.t_max / settings.steps;
    m.start_positive = ray.f_start >= 0.0;
    m.f_a = ray.f_start;
    going.push_back(r);
  }
  std::vector<Vec3> points;
  std::vector<double> values;
  while (!going.empty()) {
    points.clear();
    for (const std::size_t r : going) {
      MarchingRay& m = state[r];
      m.t_query = m.root ? m.root->next() : (m.i == settings.steps ? m.t_max : m.i * m.step);
      points.push_back(m.start + m.t_query * m.d);
    }
    values.resize(points.size());
    f.values(points, values);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < going.size(); ++k) {
      const std::size_t r = going[k];
      MarchingRay& m = state[r];
      const double g = values[k];
      if (m.root) {
        m.root->feed(g);
      } else if ((g >= 0.0) != m.start_positive) {
        m.root.emplace(m.t_a, m.f_a, m.t_query, g, settings.tolerance * scale);
      } else {
        m.t_a = m.t_query;
        m.f_a = g;
        if (++m.i > settings.steps) continue;  // left the region without a crossing
        if (curved) {
          // Within curved bounds (a concave region), a ray that has been inside and leaves is done.
          const bool in = curved->inside(points[k]);
          if (m.was_inside && !in) continue;
          m.was_inside = m.was_inside || in;
        }
      }
      if (m.root && m.root->done()) {
        const double t = m.root->result();
        out[r] = hit_at(m.start + t * m.d, m.d, t);
        continue;
      }
      going[kept++] = r;
    }
    going.resize(kept);
  }
}

void evaluate_starts(const Sampler& f, std::span<RayStart> rays) {
  std::vector<Vec3> starts(rays.size());
  for (std::size_t k = 0; k < rays.size(); ++k) starts[k] = rays[k].start;
  std::vector<double> values(rays.size());
  f.values(starts, values);
  for (std::size_t k = 0; k < rays.size(); ++k) rays[k].f_start = values[k];
}

std::optional<RayHit> march_to_surface(const Sampler& f, const Vec3& start, double f_start,
                                       const Vec3& direction, const Box& region,
                                       const RayMarchSettings& settings) {
  return march_to_surface(f, start, f_start, direction, MarchRegion::cell(region), settings);
}

std::optional<RayHit> march_to_surface(const Sampler& f, const Vec3& start, double f_start,
                                       const Vec3& direction, const MarchRegion& region,
                                       const RayMarchSettings& settings) {
  const RayStart ray{start, f_start, direction};
  std::vector<std::optional<RayHit>> hit;
  march_rays(f, std::span<const RayStart>(&ray, 1), region, settings, hit);
  return hit[0];
}

}  // namespace isopatch
