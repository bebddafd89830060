#pragma once
/// \file ray_march.hpp
/// Projection of a point onto f = 0 along a given direction within a region (march_region.hpp: a box
/// cell, a convex cell cut by planes, or a composite patch's curved region), as in Sipos & Salvi 2021,
/// sec. 2.2 and 4, made robust as in docs/algorithms.md 4.6: march in fixed steps from the start towards
/// the side where f changes sign, stop at the region's exit, then refine the bracket. The one ray march
/// of the library: sides, patches and fans of every path use it.

#include <isopatch/geometry.hpp>

#include <optional>
#include <span>
#include <vector>

#include "projection/march_region.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

struct RayMarchSettings {
  int steps = 32;             ///< march steps per traversal of the region (K)
  double tolerance = 1e-13;   ///< final bracket width, as a fraction of the region's scale
  double exit_margin = 1e-6;  ///< the march may leave the region's box by this fraction of its scale
};

struct RayHit {
  Vec3 point;          ///< on f = 0 (to the tolerance)
  Vec3 ray_direction;  ///< unit direction of travel (towards the crossing)
  double distance;     ///< distance travelled from the start
};

/// Moves `start` along +direction or -direction (whichever goes from the sign of f(start) to the
/// other, given that `direction` points to the positive side) to the first crossing of f = 0 within
/// `region` (grown by the exit margin).
/// \pre direction is non-zero; start lies in the grown region.
/// \return the crossing, or nullopt when the ray leaves the region without crossing.
/// \throw EvaluationError if f is not finite along the way.
/// (march_rays with this one ray: one implementation of the march.)
std::optional<RayHit> march_to_surface(const Sampler& f, const Vec3& start, double f_start,
                                       const Vec3& direction, const Box& region,
                                       const RayMarchSettings& settings = {});

/// One ray of march_rays: the arguments of one march_to_surface call.
struct RayStart {
  Vec3 start;
  double f_start = 0.0;  ///< f(start)
  Vec3 direction;        ///< towards the positive side of f; a zero direction gives no hit
};

/// march_to_surface for many rays in one region: out[i] is the march of rays[i] (its first crossing
/// of f = 0 within the grown region, or nullopt), with f evaluated in batches (Sampler::values), one
/// point of every ray still going per round: far cheaper per point than one value at a time, and the
/// same points, hence the same values and the same hit, as a ray marched alone (docs/algorithms.md 4.6).
/// \pre every start lies in the grown region. \post out.size() == rays.size().
/// \throw EvaluationError if f is not finite at a point some ray evaluates (the first of its batch).
void march_rays(const Sampler& f, std::span<const RayStart> rays, const Box& region,
                const RayMarchSettings& settings, std::vector<std::optional<RayHit>>& out);

/// The general march: each ray goes at most `region.reach`, and no further than the exit of
/// `region.box` grown by the exit margin, in `settings.steps` equal steps; with curved bounds a ray
/// that has been inside them and leaves stops, and a start outside them is allowed. A crossing that
/// `region.admits()` not (beyond a plane or a curved bound) is no hit. f is evaluated in batches as
/// above; the bounds one point at a time.
/// \pre every start lies in the grown box. \post out.size() == rays.size().
/// \throw EvaluationError if f or a bound is not finite at a point some ray evaluates.
void march_rays(const Sampler& f, std::span<const RayStart> rays, const MarchRegion& region,
                const RayMarchSettings& settings, std::vector<std::optional<RayHit>>& out);

/// One ray of the general march. \throw EvaluationError as march_rays.
std::optional<RayHit> march_to_surface(const Sampler& f, const Vec3& start, double f_start,
                                       const Vec3& direction, const MarchRegion& region,
                                       const RayMarchSettings& settings);

/// Fills rays[k].f_start with f(rays[k].start), all in one batch (Sampler::values).
/// \throw EvaluationError if f is not finite at a start.
void evaluate_starts(const Sampler& f, std::span<RayStart> rays);

/// Distance along the unit direction `d` from `p` (inside `box`) to the box boundary (slab test).
double exit_distance(const Vec3& p, const Vec3& d, const Box& box);

}  // namespace isopatch
