#pragma once
/// \file fan_centre.hpp
/// The fallback of the projection mesher for a patch still rejected after refinement (docs/algorithms.md
/// 4.7): its boundary polygon fanned around one centre vertex, the centroid moved onto f = 0. One
/// fallback for octree cells, convex cells and composite patches.

#include <isopatch/geometry.hpp>

#include <span>

#include "projection/march_region.hpp"
#include "projection/surface_point.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

struct FanCentre {
  SurfacePoint point;      ///< on f = 0 when projected; else the centroid (with `direction` as gradient)
  bool projected = false;  ///< whether a ray found f = 0
};

/// The centre of a fan over `polygon`: its centroid marched onto f = 0 within `region` along
/// `direction` (skipped when zero), else along grad f at the centroid.
/// \pre polygon is not empty. \param march_steps  K of the march (ProjectionParams::march_steps)
/// \throw EvaluationError when f, grad f or a bound is not finite where evaluated.
FanCentre fan_centre(const Sampler& f, std::span<const Vec3> polygon, const Vec3& direction,
                     const MarchRegion& region, int march_steps);

}  // namespace isopatch
