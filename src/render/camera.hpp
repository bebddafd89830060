#pragma once
// The renderer's camera: a view of the mesh's bounding sphere from an azimuth and an elevation,
// mapping world points to pixel positions and view depths (see render.hpp for the conventions).

#include <isopatch/geometry.hpp>
#include <isopatch/render.hpp>

#include <vector>

namespace isopatch::render {

/// A world point seen by the camera: pixel position (x right, y down, pixel centres at +0.5) and
/// depth, the distance from the eye along the view axis (always > 0; smaller is nearer).
struct ScreenPoint {
  double x = 0.0;
  double y = 0.0;
  double depth = 0.0;
};

/// A rectangle of the canvas, in pixels.
struct Viewport {
  double x0 = 0.0;
  double y0 = 0.0;
  double width = 0.0;
  double height = 0.0;
};

struct Camera {
  Vec3 centre = Vec3::Zero();          ///< centre of the bounding sphere
  double radius = 1.0;                 ///< radius of the bounding sphere
  Vec3 right = Vec3::UnitX();          ///< camera x in world coordinates
  Vec3 up = Vec3::UnitY();             ///< camera y
  Vec3 toward_viewer = Vec3::UnitZ();  ///< camera z
  bool perspective = true;
  double eye_distance = 1.0;  ///< from the eye to the centre
  double focal = 1.0;         ///< pixels per unit of x/depth (perspective) or of x (orthographic)
  double cx = 0.0;            ///< pixel position of the view axis
  double cy = 0.0;

  ScreenPoint project(const Vec3& p) const;
  /// A world direction in camera coordinates.
  Vec3 to_camera(const Vec3& v) const { return Vec3(v.dot(right), v.dot(up), v.dot(toward_viewer)); }
  /// Weight of a vertex in perspective-correct interpolation (1/depth, or 1 when orthographic).
  double interpolation_weight(double depth) const { return perspective ? 1.0 / depth : 1.0; }
};

/// The camera that frames the bounding sphere of `points` (centre of their box, smallest radius about
/// it; radius 1 for a single point) inside `viewport` with a small margin.
/// \pre options' angles and field of view are valid (render_mesh checks them); points not empty.
Camera fit_camera(const std::vector<Vec3>& points, const RenderOptions& options, const Viewport& viewport);

}  // namespace isopatch::render
