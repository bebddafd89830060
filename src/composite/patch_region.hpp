#pragma once
/// \file patch_region.hpp
/// The region of space that holds one patch of a composite, { x : b(x) >= 0 for every bound b }, which
/// may be bounded by curved surfaces and be concave (Sipos & Salvi 2021, sec. 4: "space partitions
/// bounded by nonplanar surfaces"), and the march of a point onto the patch's function along a
/// direction without leaving it: the signs of f and of every bound are sampled along the ray and the
/// first crossing of f = 0 inside the region is bracketed and refined (the ray march of the paper's
/// sec. 2.2, bounded by the region instead of an octree cell).

#include <isopatch/geometry.hpp>

#include <optional>
#include <vector>

#include "ipatch/composite.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

class PatchRegion {
 public:
  /// \param tolerance  how far (in the first-order distance b / |grad b|) a point may lie outside a bound
  ///                   and still count as inside; >= 0
  PatchRegion(const CompositePatch& patch, double tolerance);

  /// min over the bounds of b(x) / |grad b(x)| (a signed first-order distance to the nearest bound,
  /// positive inside); +infinity without bounds.
  /// \throw EvaluationError when a bound or its gradient is not finite at x.
  double depth(const Vec3& x) const;
  bool inside(const Vec3& x) const { return depth(x) >= -tolerance_; }
  double tolerance() const { return tolerance_; }

 private:
  const std::vector<SurfacePtr>& bounds_;
  double tolerance_;
};

struct RegionHit {
  Vec3 point;      ///< on f = 0 to about 1e-13 of the march length
  Vec3 gradient;   ///< grad f there
  Vec3 direction;  ///< unit direction of travel
};

/// Marches from `start` along +direction or -direction (the way from the sign of f(start) to the
/// other; `direction` points to the positive side of f) in `steps` equal steps over at most
/// `max_distance`, and returns the first crossing of f = 0 that lies inside the region. The march
/// stops without a hit once it has been inside the region and leaves it. A start outside the region
/// (a base point beyond a curved bound) is allowed: only crossings inside count.
/// \pre direction non-zero; max_distance > 0; steps >= 1.
/// \throw EvaluationError when f or a bound is not finite where evaluated.
std::optional<RegionHit> march_in_region(const Sampler& f, const PatchRegion& region, const Vec3& start,
                                         double f_start, const Vec3& direction, double max_distance,
                                         int steps);

}  // namespace isopatch
