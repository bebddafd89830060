#pragma once
// One n-sided patch of the projection mesher (Sipos & Salvi 2021, eq. 1 and sec. 2.2; method.md 7.1,
// 8.1-8.3): the barycentric base p(x) = sum_k lambda_k(x) Q_k at every interior template vertex, moved
// onto f = 0 along d(x) = sum_k lambda_k(x) d_k within the cell, then the acceptance tests.

#include <vector>

#include "patch/patch_template.hpp"
#include "project/surface_point.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

enum class PatchVerdict {
  Accepted,
  RayMissed,  ///< a ray left the cell without meeting f = 0
  RayAngle,   ///< a ray met f = 0 at more than the acceptance angle to grad f
  Flipped,    ///< a triangle's normal opposes the gradients at its vertices
};

struct PatchStats {
  std::size_t gradient_rays = 0;  ///< interior vertices projected along grad f instead of d(x)
};

/// \param corner_positions, corner_directions  Q_k and unit d_k (towards the positive side), k = 0..n-1
/// \param points  one entry per template vertex; boundary entries (corners and sides) filled in by the
///                caller, interior entries are written here
/// When the interpolated ray misses f = 0 inside the cell or meets it beyond the acceptance angle, the
/// vertex is marched along grad f at its base point instead (counted in `stats`).
/// \return the verdict; on Accepted every entry of `points` lies on f = 0
/// \throw EvaluationError when f or grad f is not finite where evaluated
PatchVerdict project_patch(const Sampler& f, const PatchTemplate& patch, const std::vector<Vec3>& corner_positions,
                           const std::vector<Vec3>& corner_directions, const Box& cell,
                           const ProjectionParams& params, std::vector<SurfacePoint>& points,
                           PatchStats& stats);

/// The flip test alone: every triangle's normal has a positive dot product with the sum of the
/// gradients at its vertices.
bool triangles_agree_with_gradient(const PatchTemplate& patch, const std::vector<SurfacePoint>& points);

}  // namespace isopatch
