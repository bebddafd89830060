#pragma once
// The face curve between two consecutive corners of a loop: the intersection of the cell face's plane
// with f = 0, traced as a dense polyline (docs/algorithms.md 4.4) and resampled at equal arc length to
// the boundary vertices of both patches sharing the side. It gives the Coons base (Salvi 2020) its
// boundary curves and places boundary vertices evenly along the true curve rather than at the hits
// of rays from evenly spaced chord points (Sipos & Salvi 2021, sec. 2.2, "boundary points stay in place").

#include <vector>

#include "partition/cell_partition.hpp"
#include "projection/surface_point.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

struct FaceCurve {
  /// M + 1 points (M = max(16, 4 r)) from `from` to `to`, both corners included exactly; the inner ones
  /// are chord points moved onto f = 0 within the face along the interpolated corner directions.
  std::vector<Vec3> dense;
  /// The r - 1 inner boundary vertices at arc length i / r of the polyline (i = 1..r-1), each moved
  /// onto f = 0 along the in-face gradient: on f = 0 and exactly in the face plane.
  std::vector<SurfacePoint> points;
  /// Every ray hit inside the face at an in-face angle within params.cos_max_boundary_angle. When false,
  /// missed points stand unprojected in their place, and the side must not be used for a patch.
  bool accepted = true;
};

/// Dense samples per side for resolution r: max(16, 4 r).
int face_curve_samples(int resolution);

/// Traces the side from corner `from` to corner `to` on `face`.
/// \pre both crossings lie on edges of the face.
/// \throw EvaluationError when f is not finite along a ray.
FaceCurve trace_face_curve(const Sampler& f, const CellCorner& from, const CellCorner& to,
                           const CellFace& face, const ProjectionParams& params);

}  // namespace isopatch
