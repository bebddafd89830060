/// \file patch_projection.cpp
/// The projection of one patch (patch_projection.hpp).
#include "projection/patch_projection.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "projection/ray_march.hpp"

namespace isopatch {

ProjectionParams projection_params(const ProjectionSettings& s, int resolution) {
  const double to_radians = std::numbers::pi / 180.0;
  ProjectionParams p;
  p.resolution = resolution;
  p.march_steps = s.march_steps;
  p.cos_max_ray_angle = std::cos(s.max_ray_angle * to_radians);
  p.cos_max_boundary_angle = std::cos(s.max_boundary_ray_angle * to_radians);
  return p;
}

bool triangles_agree_with_gradient(const PatchTemplate& patch, const std::vector<SurfacePoint>& points) {
  for (const TemplateTriangle& t : patch.triangles()) {
    const SurfacePoint& a = points[static_cast<std::size_t>(t[0])];
    const SurfacePoint& b = points[static_cast<std::size_t>(t[1])];
    const SurfacePoint& c = points[static_cast<std::size_t>(t[2])];
    // Template vertices merged onto one side point (a side with fewer segments) give triangles that
    // are dropped from the mesh: they cannot flip.
    if (a.position == b.position || b.position == c.position || c.position == a.position) continue;
    const Vec3 normal = (b.position - a.position).cross(c.position - a.position);
    if (!(normal.dot(a.gradient.normalized() + b.gradient.normalized() + c.gradient.normalized()) > 0.0))
      return false;
  }
  return true;
}

PatchVerdict project_patch(const Sampler& f, const PatchTemplate& patch, const BaseSurface& base_surface,
                           const std::vector<Vec3>& corner_directions, const MarchRegion& region,
                           const ProjectionParams& params, std::vector<SurfacePoint>& points,
                           PatchStats& stats) {
  const int n = patch.sides();
  const Box& cell = region.box;
  RayMarchSettings march;
  march.steps = params.march_steps;
  // Every interior vertex's base point and ray first, f at the base points and the marches in batches
  // (march_rays: the same hits as one march at a time, far cheaper per evaluation); then the tests in
  // vertex order, so the verdict is the one the first failing vertex gives.
  std::vector<std::size_t> interior;
  std::vector<RayStart> rays;
  std::vector<char> clamped;
  for (std::size_t v = 0; v < patch.vertex_count(); ++v) {
    if (patch.tag(static_cast<int>(v)).kind != VertexTag::Kind::Interior) continue;
    const auto lambda = patch.lambda(static_cast<int>(v));
    Vec3 base = base_surface.evaluate(lambda);
    // The march needs a start inside the cell. A barycentric base is inside by convexity (up to
    // rounding, which the margin absorbs); a Coons base may bulge out where a face curve bends away.
    const bool outside = !cell.contains(base, MarchRegion::kPlaneMargin * region.scale);
    if (outside) base = base.cwiseMax(cell.lo).cwiseMin(cell.hi);
    Vec3 direction = Vec3::Zero();
    for (int k = 0; k < n; ++k)
      direction += lambda[static_cast<std::size_t>(k)] * corner_directions[static_cast<std::size_t>(k)];
    interior.push_back(v);
    clamped.push_back(outside ? 1 : 0);
    rays.push_back({base, 0.0, direction});
  }
  evaluate_starts(f, rays);
  std::vector<std::optional<RayHit>> hits;
  march_rays(f, rays, region, march, hits);
  auto acceptable = [&](const RayHit& h, ValueGradient& vg) {
    vg = f.value_gradient(h.point);
    const double norm = vg.gradient.norm();
    return norm > 0.0 && std::abs(h.ray_direction.dot(vg.gradient)) >= params.cos_max_ray_angle * norm;
  };
  for (std::size_t k = 0; k < interior.size(); ++k) {
    if (clamped[k]) ++stats.clamped_base_points;
    std::optional<RayHit>& hit = hits[k];
    ValueGradient vg;
    if (!hit || !acceptable(*hit, vg)) {
      // Where the interpolated direction grazes the surface (typically a cell that the surface nearly
      // touches along a face), an interior vertex may instead move along grad f at its base point:
      // only boundary vertices must keep to their face planes.
      ++stats.gradient_rays;
      const RayStart& ray = rays[k];
      hit = march_to_surface(f, ray.start, ray.f_start, f.value_gradient(ray.start).gradient, region, march);
      if (!hit) return PatchVerdict::RayMissed;
      if (!acceptable(*hit, vg)) return PatchVerdict::RayAngle;
    }
    points[interior[k]] = {hit->point, vg.gradient};
  }
  return triangles_agree_with_gradient(patch, points) ? PatchVerdict::Accepted : PatchVerdict::Flipped;
}

}  // namespace isopatch
