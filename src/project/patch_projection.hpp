#pragma once
// One n-sided patch of the projection mesher (Sipos & Salvi 2021, eq. 1 and sec. 2.2; docs/algorithms.md
// 3.5, 4.5-4.7): a base surface (barycentric, eq. 1, or the multi-sided C0 Coons patch of Salvi 2020)
// sampled at every interior template vertex, moved onto f = 0 along d(x) = sum_k lambda_k(x) d_k
// within the cell, then the acceptance tests.

#include <span>
#include <vector>

#include "partition/cell_partition.hpp"
#include "patch/base_surface.hpp"
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
  std::size_t gradient_rays = 0;        ///< interior vertices projected along grad f instead of d(x)
  std::size_t clamped_base_points = 0;  ///< base points outside the cell, moved to its nearest point
};

/// \param base  the base surface, base.sides() == patch.sides()
/// \param corner_directions  d_k, k = 0..n-1, each pointing to the positive side of f (not necessarily
///                           unit: the cell-edge directions, or unit gradients for the Coons base)
/// \param points  one entry per template vertex; boundary entries (corners and sides) filled in by the
///                caller, interior entries are written here
/// A base point outside the cell (a Coons patch may bulge out of it) starts from the nearest point of
/// the cell instead (counted in `stats`). When the interpolated ray misses f = 0 inside the cell or
/// meets it beyond the acceptance angle, the vertex is marched along grad f at its base point instead
/// (counted in `stats`).
/// \param planes  a general convex cell's planes (empty: the cell is `cell`): a ray meeting f = 0
///                beyond one of them (by more than 1e-9 of the cell's diagonal) has missed
/// \return the verdict; on Accepted every entry of `points` lies on f = 0
/// \throw EvaluationError when f or grad f is not finite where evaluated
PatchVerdict project_patch(const Sampler& f, const PatchTemplate& patch, const BaseSurface& base,
                           const std::vector<Vec3>& corner_directions, const Box& cell,
                           const ProjectionParams& params, std::vector<SurfacePoint>& points,
                           PatchStats& stats, std::span<const CellPlane> planes = {});

/// The flip test alone: every triangle's normal has a positive dot product with the sum of the
/// gradients at its vertices.
bool triangles_agree_with_gradient(const PatchTemplate& patch, const std::vector<SurfacePoint>& points);

}  // namespace isopatch
