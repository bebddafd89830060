#pragma once
/// \file curve_point.hpp
/// Points where two or three smooth functions vanish together: the Newton iterations that put a point
/// on a crease of a CSG shape (f_i = f_j = 0) or on a corner (f_i = f_j = f_k = 0). Two equations in
/// three unknowns take the minimum-norm (Gauss-Newton) step x <- x - J^T (J J^T)^-1 g, which moves a
/// point near the curve to a point of it close to the start (Allgower & Georg, "Introduction to
/// Numerical Continuation Methods", 2003, ch. 3); three equations take the plain Newton step.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <optional>

namespace isopatch {

/// How the iterations stop.
struct CurvePointParams {
  double tolerance = 0.0;   ///< converged when every |g| / |grad g| <= tolerance (> 0)
  double max_step = 0.0;    ///< no step longer than this (> 0)
  double max_travel = 0.0;  ///< fails once the point is farther than this from the start (> 0)
  int max_iterations = 40;
};

/// The point of a = b = 0 that minimum-norm Newton steps reach from `start`, or nullopt when the
/// gradients are (nearly) parallel on the way (a tangential contact: no curve to settle on), a value
/// is not finite, the point travels too far, or the iterations do not converge.
std::optional<Vec3> settle_on_curve(const Surface& a, const Surface& b, const Vec3& start,
                                    const CurvePointParams& params);

/// The point of a = b = c = 0 that Newton steps reach from `start`, or nullopt as settle_on_curve()
/// (the three gradients nearly dependent: the surfaces do not meet in an isolated point there).
std::optional<Vec3> settle_on_corner(const Surface& a, const Surface& b, const Surface& c, const Vec3& start,
                                     const CurvePointParams& params);

/// The sine of the angle between the gradients of a and b at p (0 when either vanishes).
double gradient_sine(const Surface& a, const Surface& b, const Vec3& p);

}  // namespace isopatch
