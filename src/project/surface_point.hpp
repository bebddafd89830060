#pragma once
// A vertex of the projection mesher: a point on f = 0 with grad f there (for acceptance tests).

#include <isopatch/geometry.hpp>

namespace isopatch {

struct SurfacePoint {
  Vec3 position = Vec3::Zero();
  Vec3 gradient = Vec3::Zero();
};

/// Parameters of projection and acceptance shared by sides and patches (from Settings).
struct ProjectionParams {
  int resolution = 8;                 ///< r: segments per side
  int march_steps = 32;               ///< K
  double cos_max_ray_angle = 0.2588;  ///< cos of the interior acceptance angle
  double cos_max_boundary_angle = 0.1736;
};

}  // namespace isopatch
