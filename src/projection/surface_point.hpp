#pragma once
/// \file surface_point.hpp
/// A vertex of the projection mesher: a point on f = 0 with grad f there (for acceptance tests), and
/// the projection's parameters as the ray march and the acceptance tests read them.

#include <isopatch/geometry.hpp>
#include <isopatch/stage_settings.hpp>

#include <cmath>
#include <numbers>

namespace isopatch {

struct SurfacePoint {
  Vec3 position = Vec3::Zero();
  Vec3 gradient = Vec3::Zero();
};

/// Parameters of projection and acceptance shared by sides and patches, every path's (from Settings:
/// projection_params()).
struct ProjectionParams {
  int resolution = 8;  ///< r: segments per side (cells; a composite patch takes its curves' counts)
  int march_steps = ProjectionSettings{}.march_steps;  ///< K
  /// cos of the interior acceptance angle (ProjectionSettings::max_ray_angle's default)
  double cos_max_ray_angle = std::cos(ProjectionSettings{}.max_ray_angle * std::numbers::pi / 180.0);
  /// cos of the boundary (in-face) acceptance angle (ProjectionSettings::max_boundary_ray_angle's default)
  double cos_max_boundary_angle =
      std::cos(ProjectionSettings{}.max_boundary_ray_angle * std::numbers::pi / 180.0);
};

/// The parameters for `settings`, the angles' cosines taken once. \param resolution  r
ProjectionParams projection_params(const ProjectionSettings& settings, int resolution);

}  // namespace isopatch
