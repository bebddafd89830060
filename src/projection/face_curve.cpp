// Face curves by projected chord points (docs/algorithms.md 4.4); see face_curve.hpp.
#include "projection/face_curve.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "ngon/polyline_curve.hpp"
#include "projection/ray_march.hpp"
#include "projection/side_points.hpp"

namespace isopatch {
namespace {

/// One point moved onto f = 0 within the face, with the in-face angle test of docs/algorithms.md 4.3.
struct InFaceHit {
  SurfacePoint point;
  bool accepted = false;
};

InFaceHit project_in_face(const Sampler& f, const Vec3& start, const Vec3& direction, const CellFace& face,
                          const ProjectionParams& params) {
  RayMarchSettings march;
  march.steps = params.march_steps;
  const auto hit = march_to_surface(f, start, f.value(start), direction, face.region, march);
  if (!hit) return {{start, f.value_gradient(start).gradient}, false};
  const ValueGradient vg = f.value_gradient(hit->point);
  const Vec3 in_face = in_plane(face, vg.gradient);
  const double norm = in_face.norm();
  const bool steep =
      norm > 0.0 && std::abs(hit->ray_direction.dot(in_face)) >= params.cos_max_boundary_angle * norm;
  return {{hit->point, vg.gradient}, steep};
}

}  // namespace

int face_curve_samples(int resolution) {
  return std::max(16, 4 * resolution);
}

FaceCurve trace_face_curve(const Sampler& f, const CellCorner& from, const CellCorner& to,
                           const CellFace& face, const ProjectionParams& params) {
  // Every start point is put into the face plane through a corner (corners lie on the face's edges
  // exactly), so that the rounding of (1 - t) a + t b cannot leave the plane.
  const int m = face_curve_samples(params.resolution);
  FaceCurve curve;
  curve.dense.reserve(static_cast<std::size_t>(m) + 1);
  curve.dense.push_back(from.position);
  for (int j = 1; j < m; ++j) {
    const double t = static_cast<double>(j) / m;
    const Vec3 start = onto_plane(face, (1.0 - t) * from.position + t * to.position, from.position);
    // Both corner directions are edge directions of this face: their blend lies in its plane and never
    // vanishes (docs/algorithms.md 4.5).
    const Vec3 direction = in_plane(face, (1.0 - t) * from.direction + t * to.direction);
    const InFaceHit hit = project_in_face(f, start, direction, face, params);
    curve.accepted = curve.accepted && hit.accepted;
    curve.dense.push_back(hit.point.position);
  }
  curve.dense.push_back(to.position);
  if (!((to.position - from.position).norm() > 0.0)) {
    curve.accepted = false;  // coinciding corners (f = 0 at a lattice vertex): no curve to trace
    for (int i = 1; i < params.resolution; ++i) curve.points.push_back({from.position, from.gradient});
    return curve;
  }
  const PolylineCurve polyline(curve.dense);
  curve.points.reserve(static_cast<std::size_t>(std::max(params.resolution - 1, 0)));
  for (int i = 1; i < params.resolution; ++i) {
    // The arc-length sample lies on a chord of the polyline, within O(h^2 curvature) of f = 0: a short
    // march along the in-face gradient puts it on the curve.
    const Vec3 start =
        onto_plane(face, polyline.point(static_cast<double>(i) / params.resolution), from.position);
    const Vec3 direction = in_plane(face, f.value_gradient(start).gradient);
    const InFaceHit hit = project_in_face(f, start, direction, face, params);
    curve.accepted = curve.accepted && hit.accepted;
    curve.points.push_back(hit.point);
  }
  return curve;
}

}  // namespace isopatch
