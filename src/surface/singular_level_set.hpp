#pragma once
// Detection of a degenerate input: f = 0 where grad f vanishes on (most of) the surface, as for a
// repeated factor f = g^k (k >= 2 odd, so f still changes sign). The zero set may be a fine surface, but
// everything the projection mesher derives from grad f breaks there: Newton projection converges only
// linearly, the exact curvature formulas (Goldman 2005) divide a difference of equal terms of order
// g^(2k-1) by |grad f|^3 and return rounding noise, so --max-error asks for the smallest cells everywhere
// and the clean-up leaves slivers. Such an f is rejected up front with a one-line SingularSurfaceError.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>

namespace isopatch {

/// What a sample of f = 0 showed about grad f there.
struct SingularEvidence {
  std::size_t roots = 0;        ///< crossings of f = 0 examined
  std::size_t singular = 0;     ///< of which grad f vanished (relative to the slope of f across the surface)
  Vec3 example = Vec3::Zero();  ///< one singular crossing (when singular > 0)
};

/// Sample points per axis of the grid whose edge crossings are examined.
inline constexpr int kSingularCheckSamples = 16;
/// At most this many crossings are examined (spread evenly over all crossing grid edges).
inline constexpr std::size_t kSingularCheckRoots = 64;

/// Finds crossings of f = 0 on the edges of a regular grid of kSingularCheckSamples^3 points in `box`
/// (shifted by non-dyadic fractions, like the zero-function check), locates each by a bracketed root,
/// and calls it singular when |grad f| there is below 1e-3 of the slope of f across the crossing (the
/// central difference of f along the edge over a quarter of a grid step). At a regular crossing the
/// two agree up to the angle between the edge and the surface, so the ratio is at least of order 1; at
/// a root of multiplicity k >= 2 the gradient is of order (root error)^(k-1), i.e. rounding noise.
/// Crossings where f is not finite are skipped. Never throws.
/// \pre box.valid().
SingularEvidence singular_level_set_evidence(const Surface& surface, const Box& box);

/// Throws SingularSurfaceError with a one-line message naming the share of singular crossings and one
/// of them when at least kSingularShare of at least 8 examined crossings are singular; does nothing for
/// an invalid box (the meshers report that).
void reject_singular_level_set(const Surface& surface, const Box& box);

/// Share of singular crossings from which f = 0 is rejected. Isolated singular points and curves (a cone
/// apex, two sheets crossing) hold no grid crossing at all with probability 1: the share is for
/// repeated factors, which are singular everywhere they apply.
inline constexpr double kSingularShare = 0.1;

}  // namespace isopatch
