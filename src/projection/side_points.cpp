#include "projection/side_points.hpp"

#include <cmath>
#include <optional>
#include <vector>

#include "projection/ray_march.hpp"

namespace isopatch {

SidePoints sample_side(const Sampler& f, const CellCorner& from, const CellCorner& to, const CellFace& face,
                       const ProjectionParams& params) {
  const int r = params.resolution;
  const Box& region = face.region;
  RayMarchSettings march;
  march.steps = params.march_steps;
  // Every sample's start and ray first, then f at the starts and the marches in batches.
  std::vector<RayStart> rays;
  for (int j = 1; j < r; ++j) {
    const double t = static_cast<double>(j) / r;
    // Both corner directions are cell-edge directions of this face: the sum lies in its plane and is
    // never zero (adjacent edges are perpendicular, opposite ones point the same way).
    // The start is put into the face plane through a corner: (1 - t) a + t b rounds off a plane both
    // corners lie on exactly, and a side on a box face must stay on it (the clean-up slides and merges
    // only vertices exactly on one box face).
    rays.push_back({onto_plane(face, (1.0 - t) * from.position + t * to.position, from.position), 0.0,
                    (1.0 - t) * from.direction + t * to.direction});
  }
  evaluate_starts(f, rays);
  std::vector<std::optional<RayHit>> hits;
  march_rays(f, rays, region, march, hits);
  SidePoints side;
  side.points.reserve(rays.size());
  for (std::size_t k = 0; k < rays.size(); ++k) {
    const std::optional<RayHit>& hit = hits[k];
    if (!hit) {
      side.accepted = false;
      side.points.push_back({rays[k].start, f.value_gradient(rays[k].start).gradient});
      continue;
    }
    const ValueGradient vg = f.value_gradient(hit->point);
    const Vec3 in_face = in_plane(face, vg.gradient);
    const double norm = in_face.norm();
    if (!(norm > 0.0) || std::abs(hit->ray_direction.dot(in_face)) < params.cos_max_boundary_angle * norm)
      side.accepted = false;
    side.points.push_back({hit->point, vg.gradient});
  }
  return side;
}

}  // namespace isopatch
