#pragma once
// Projection of a point onto f = 0 along a given direction, bounded by a convex region (a box), as in
// Sipos & Salvi 2021, section 2.2, made robust as in docs/algorithms.md 4.6: march in fixed steps from
// the start towards the side where f changes sign, stop at the region's exit, then refine the bracket.

#include <isopatch/geometry.hpp>

#include <optional>
#include <span>
#include <vector>

#include "surface/sampler.hpp"

namespace isopatch {

struct RayMarchSettings {
  int steps = 32;             ///< march steps per traversal of the region (K)
  double tolerance = 1e-13;   ///< final bracket width, as a fraction of the region's diagonal
  double exit_margin = 1e-6;  ///< the march may leave the region by this fraction of its diagonal
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

/// Fills rays[k].f_start with f(rays[k].start), all in one batch (Sampler::values).
/// \throw EvaluationError if f is not finite at a start.
void evaluate_starts(const Sampler& f, std::span<RayStart> rays);

/// Distance along the unit direction `d` from `p` (inside `box`) to the box boundary (slab test).
double exit_distance(const Vec3& p, const Vec3& d, const Box& box);

}  // namespace isopatch
