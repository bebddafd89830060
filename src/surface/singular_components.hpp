#pragma once
// The second half of find_singular_points() (singular_points.hpp): converged Gauss-Newton points merged
// at a spacing and grouped into components (isolated points and curves), and the text that names them.

#include <isopatch/singular_points.hpp>

#include <cstddef>
#include <vector>

namespace isopatch::singular {

/// A Gauss-Newton run that was accepted.
struct Converged {
  Vec3 point = Vec3::Zero();
  double residual = 0.0;  ///< |grad f| / G at the point (see SingularSearchSettings::tolerance)
  std::size_t start = 0;  ///< index of its start (ties of residual broken by it, so the order is fixed)
};

/// Merges `found` at `spacing`: by increasing residual, then start, a point closer than `spacing` to
/// one kept before it is dropped. The result does not depend on the order of `found`.
/// \pre spacing > 0 and finite.
std::vector<Converged> merge_converged(std::vector<Converged> found, double spacing);

/// Whether f = 0 is one smooth sheet through p although grad f(p) = 0: the sign of f at 256 points of
/// the sphere of `radius` about p (a Fibonacci lattice) is that of a half-space through p (at least 95%
/// of the points farther than 0.2 radius from its plane agree). It is for a smooth sheet, whatever the
/// order to which f vanishes across it (the heart's equator, where f = (u - c^(1/3) z)(...)); at a node,
/// a crossing of sheets or tangent sheets the leading form of f is even and no half-space matches; at a
/// cusp the sign changes only on a small cap. Non-finite values count as no agreement.
bool smooth_sheet(const Surface& surface, const Vec3& p, double radius);

/// Joins the points of `kept` of the same kind (`smooth[i]`) closer than kJoinSpacings * spacing into
/// components (one point: isolated, more: a curve) and fills `out->points`, `out->components` and
/// `out->degenerate` as singular_points.hpp describes. \pre smooth.size() == kept.size().
void group_points(const std::vector<Converged>& kept, const std::vector<bool>& smooth, double spacing,
                  SingularPoints* out);

/// Points closer than this many spacings belong to one component.
inline constexpr double kJoinSpacings = 3.0;

}  // namespace isopatch::singular
