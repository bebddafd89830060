#pragma once
// Detection of a degenerate input: f identically zero on the box. Then every point is on f = 0, the
// zero set is a solid rather than a 2-manifold, and the sign rule (f >= 0 positive) sees no crossing
// anywhere, while interval pruning cannot exclude a single cell ([0, 0] contains 0): without this
// check the projection mesher would subdivide the whole octree to max_depth before giving up.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <string>

namespace isopatch {

/// Evidence that f vanishes identically on a box.
enum class ZeroEvidence {
  None,      ///< f is nonzero (or not finite) somewhere it was looked at: not identically zero
  Interval,  ///< the surface's interval bound over the box is exactly [0, 0] (sound)
  Samples,   ///< f and grad f are exactly 0 at every sample of a non-dyadic 16^3 grid in the box
};

/// Sample points per axis of the grid used for ZeroEvidence::Samples.
inline constexpr int kZeroCheckSamples = 16;

/// Looks for evidence that f is identically zero on `box`. First the interval bound (when the surface
/// has one): [0, 0] proves it. Otherwise f and grad f are evaluated at kZeroCheckSamples^3 points
/// (cell centres of a regular grid shifted by non-dyadic fractions, so they avoid symmetry planes and
/// rational points); the answer is Samples only when every value and every gradient component is
/// exactly 0. Stops at the first sample that is nonzero or not finite, so a legitimate surface costs
/// one or a few evaluations. Never throws for non-finite values (the meshers report those).
/// \pre box.valid().
ZeroEvidence zero_function_evidence(const Surface& surface, const Box& box);

/// Throws NoSurfaceError with a one-line message ("no surface in the box ...: f is identically zero
/// there ...") when zero_function_evidence() finds evidence; does nothing when the box is not valid()
/// (the meshers report that).
void reject_zero_function(const Surface& surface, const Box& box);

}  // namespace isopatch
