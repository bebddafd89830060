#pragma once
/// \file patch_projection.hpp
/// One n-sided patch of the projection mesher (Sipos & Salvi 2021, eq. 1, sec. 2.2 and sec. 4;
/// docs/algorithms.md 3.5, 4.5-4.7): a base surface (barycentric, eq. 1, or the multi-sided C0 Coons
/// patch of Salvi 2020) sampled at every interior template vertex, moved onto f = 0 along
/// d(x) = sum_k lambda_k(x) d_k within the patch's region, then the acceptance tests. The one patch
/// projection of the library: octree cells, convex cells and composite patches are its producers.

#include <span>
#include <vector>

#include "ngon/base_surface.hpp"
#include "ngon/patch_template.hpp"
#include "projection/march_region.hpp"
#include "projection/surface_point.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

/// What the acceptance tests found about one patch.
enum class PatchVerdict {
  Accepted,
  RayMissed,  ///< a ray left the region without meeting f = 0 (neither along d(x) nor grad f)
  RayAngle,   ///< a ray met f = 0 at more than the acceptance angle to grad f
  Flipped,    ///< a triangle's normal opposes the gradients at its vertices
};

struct PatchStats {
  std::size_t gradient_rays = 0;        ///< interior vertices projected along grad f instead of d(x)
  std::size_t clamped_base_points = 0;  ///< base points outside the region's box, moved to its nearest point
};

/// \param base  the base surface, base.sides() == patch.sides()
/// \param corner_directions  d_k, k = 0..n-1, each pointing to the positive side of f (not necessarily
///                           unit: the cell-edge directions, or unit gradients for the Coons base)
/// \param points  one entry per template vertex; boundary entries (corners and sides) filled in by the
///                caller (their gradients only orient the flip test: any non-zero vector along the
///                normal), interior entries are written here
/// \param region  where rays may meet f = 0 (march_region.hpp): a cell's box and planes, or a
///                composite patch's curved bounds with a reach
/// A base point outside the region's box (a Coons patch may bulge out of a cell) starts from the
/// nearest point of the box instead (counted in `stats`); outside curved bounds it starts where it is.
/// When the interpolated ray misses f = 0 inside the region or meets it beyond the acceptance angle,
/// the vertex is marched along grad f at its base point instead (counted in `stats`).
/// \return the verdict; on Accepted every entry of `points` lies on f = 0
/// \throw EvaluationError when f, grad f or a bound is not finite where evaluated
PatchVerdict project_patch(const Sampler& f, const PatchTemplate& patch, const BaseSurface& base,
                           const std::vector<Vec3>& corner_directions, const MarchRegion& region,
                           const ProjectionParams& params, std::vector<SurfacePoint>& points,
                           PatchStats& stats);

/// The flip test alone: every triangle's normal has a positive dot product with the sum of the unit
/// gradients at its vertices (triangles of coinciding template vertices skipped: they are dropped).
bool triangles_agree_with_gradient(const PatchTemplate& patch, const std::vector<SurfacePoint>& points);

}  // namespace isopatch
