#include "project/side_points.hpp"

#include <cmath>

#include "project/ray_march.hpp"

namespace isopatch {

SidePoints sample_side(const Sampler& f, const CellCorner& from, const CellCorner& to, const CellFace& face,
                       const ProjectionParams& params) {
  const int r = params.resolution;
  const Box& region = face.region;
  RayMarchSettings march;
  march.steps = params.march_steps;
  SidePoints side;
  side.points.reserve(static_cast<std::size_t>(r > 1 ? r - 1 : 0));
  for (int j = 1; j < r; ++j) {
    const double t = static_cast<double>(j) / r;
    const Vec3 start = (1.0 - t) * from.position + t * to.position;
    // Both corner directions are cell-edge directions of this face: the sum lies in its plane and is
    // never zero (adjacent edges are perpendicular, opposite ones point the same way).
    const Vec3 direction = (1.0 - t) * from.direction + t * to.direction;
    const double f_start = f.value(start);
    const auto hit = march_to_surface(f, start, f_start, direction, region, march);
    if (!hit) {
      side.accepted = false;
      side.points.push_back({start, f.value_gradient(start).gradient});
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
