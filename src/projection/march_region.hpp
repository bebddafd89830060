#pragma once
/// \file march_region.hpp
/// Where a ray of the projection may look for f = 0 (Sipos & Salvi 2021, sec. 2.2 marches inside an
/// octree cell; sec. 4 inside "space partitions bounded by nonplanar surfaces"): one description for a
/// box cell, a convex cell cut by planes and a composite patch's region bounded by curved surfaces, so
/// that one ray march (ray_march.hpp) and one patch projection (patch_projection.hpp) serve them all.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <limits>
#include <span>

#include "partition/cell_partition.hpp"

namespace isopatch {

/// A region bounded by curved surfaces, { x : b(x) >= 0 for every bound b }, possibly concave, with a
/// tolerance (in the first-order distance b / |grad b|) for points just outside a bound.
class CurvedBounds {
 public:
  /// \param bounds  the bounding functions (kept by reference: they must outlive this object)
  /// \param tolerance  >= 0
  CurvedBounds(std::span<const SurfacePtr> bounds, double tolerance)
      : bounds_(bounds), tolerance_(tolerance) {}

  /// min over the bounds of b(x) / |grad b(x)|: a signed first-order distance to the nearest bound,
  /// positive inside; +infinity without bounds.
  /// \throw EvaluationError when a bound or its gradient is not finite at x.
  double depth(const Vec3& x) const;
  bool inside(const Vec3& x) const { return depth(x) >= -tolerance_; }
  double tolerance() const { return tolerance_; }

 private:
  std::span<const SurfacePtr> bounds_;
  double tolerance_;
};

/// The region a march explores: a box (possibly unbounded), optionally cut by planes and by curved
/// bounds, with a longest march.
struct MarchRegion {
  static constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  /// A march stops where it leaves this box, grown by the exit margin (RayMarchSettings).
  Box box;
  /// A crossing beyond one of these planes by more than kPlaneMargin of `scale` has missed (a convex
  /// cell of convex_partition.hpp); the march itself is bounded by `box`.
  std::span<const CellPlane> planes;
  /// A march that has been inside these bounds and leaves them stops; a crossing outside them has
  /// missed. A start outside them is allowed (a base point beyond a curved bound). Null: no such bounds.
  const CurvedBounds* curved = nullptr;
  /// The longest march, from the start.
  double reach = kUnbounded;
  /// The length tolerances are fractions of (bracket width, exit margin, plane margin): the box's
  /// diagonal for a cell, the reach for an unbounded box.
  double scale = 0.0;

  /// How far outside a plane a crossing may lie, as a fraction of `scale`: rounding of the plane
  /// equation, not geometry.
  static constexpr double kPlaneMargin = 1e-9;

  /// A cell: its box, its planes (empty for an octree cell), marches up to its boundary.
  static MarchRegion cell(const Box& box, std::span<const CellPlane> planes = {}) {
    return {box, planes, nullptr, kUnbounded, box.diagonal()};
  }
  /// A region bounded by curved surfaces only, marches of at most `reach`.
  static MarchRegion curved_region(const CurvedBounds& bounds, double reach) {
    const double inf = kUnbounded;
    return {Box{Vec3::Constant(-inf), Vec3::Constant(inf)}, {}, &bounds, reach, reach};
  }

  /// Whether `x` lies within the planes (to the margin) and the curved bounds; the box is not tested.
  /// \throw EvaluationError as CurvedBounds::depth.
  bool admits(const Vec3& x) const {
    for (const CellPlane& p : planes)
      if (p.distance(x) > kPlaneMargin * scale) return false;
    return !curved || curved->inside(x);
  }
};

}  // namespace isopatch
