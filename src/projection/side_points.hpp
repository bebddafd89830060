#pragma once
// Boundary vertices of one patch side (Sipos & Salvi 2021, sec. 2.2; docs/algorithms.md 4.3): the chord
// between two corners on a cell face, sampled at t = j/r and projected along the interpolated corner
// directions, which both lie in the face plane, so the points stay on the face curve. Computed once per
// side and read by both patches that share it.

#include <vector>

#include "partition/cell_partition.hpp"
#include "projection/surface_point.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

struct SidePoints {
  std::vector<SurfacePoint> points;  ///< the r - 1 inner vertices, from `from` (t = 1/r) towards `to`
  bool accepted = true;              ///< every ray hit inside the face at an in-face angle within the limit
};

/// Samples the side from corner `from` to corner `to` on `face` (both corners lie on edges of it).
/// When a ray misses, the chord point stands in its place (unprojected) and the side is not accepted.
/// \throw EvaluationError when f is not finite along a ray.
SidePoints sample_side(const Sampler& f, const CellCorner& from, const CellCorner& to, const CellFace& face,
                       const ProjectionParams& params);

}  // namespace isopatch
