#include "render/camera.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace isopatch::render {
namespace {

constexpr double kMargin = 0.94;  // share of the viewport the sphere's outline spans

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

}  // namespace

ScreenPoint Camera::project(const Vec3& p) const {
  const Vec3 v = p - centre;
  const double xc = v.dot(right);
  const double yc = v.dot(up);
  const double depth = eye_distance - v.dot(toward_viewer);
  const double scale = perspective ? focal / depth : focal;
  return ScreenPoint{cx + scale * xc, cy - scale * yc, depth};
}

Camera fit_camera(const std::vector<Vec3>& points, const RenderOptions& options, const Viewport& viewport) {
  Camera camera;
  Vec3 lo = points.front();
  Vec3 hi = points.front();
  for (const Vec3& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  camera.centre = 0.5 * (lo + hi);
  double radius = 0.0;
  for (const Vec3& p : points) radius = std::max(radius, (p - camera.centre).norm());
  camera.radius = radius > 0.0 ? radius : 1.0;

  // The right vector does not depend on the elevation, so looking straight down is not degenerate.
  const double az = radians(options.azimuth);
  const double el = radians(options.elevation);
  camera.toward_viewer = Vec3(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  camera.right = Vec3(-std::sin(az), std::cos(az), 0.0);
  camera.up = camera.toward_viewer.cross(camera.right);

  camera.perspective = options.camera == CameraKind::Perspective;
  const double half_side = 0.5 * kMargin * std::min(viewport.width, viewport.height);
  if (camera.perspective) {
    // At distance r / sin(a/2) the sphere's outline subtends exactly the field of view a.
    const double half_angle = 0.5 * radians(options.field_of_view);
    camera.eye_distance = camera.radius / std::sin(half_angle);
    camera.focal = half_side / std::tan(half_angle);
  } else {
    camera.eye_distance = 2.0 * camera.radius;
    camera.focal = half_side / camera.radius;
  }
  camera.cx = viewport.x0 + 0.5 * viewport.width;
  camera.cy = viewport.y0 + 0.5 * viewport.height;
  return camera;
}

}  // namespace isopatch::render
