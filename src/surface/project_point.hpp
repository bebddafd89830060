#pragma once
// Moving a point onto f = 0 by Newton steps along the gradient (the closest-point iteration for a
// level set, x <- x - f g / |g|^2), shared by the fairing baseline and the remesher.

#include <isopatch/geometry.hpp>

#include "surface/sampler.hpp"

namespace isopatch {

/// Newton steps along grad f from `p`, each at most `max_step` long, until |f| / |grad f| <= tolerance
/// (then p holds the result and the gradient there is stored in *gradient when given). Returns false,
/// leaving p at the last iterate, when the gradient vanishes or 30 steps do not converge.
/// \throw EvaluationError if f or grad f is not finite on the way.
bool project_to_surface(const Sampler& f, Vec3& p, double tolerance, double max_step,
                        Vec3* gradient = nullptr);

/// The same inside the plane x_axis = p[axis] (a face of the box): the steps use the gradient without
/// its `axis` component, so p[axis] never changes and the result lies on the curve where f = 0 meets
/// the plane; converged when |f| / |grad f in the plane| <= tolerance. Returns false as above, and when
/// grad f is normal to the plane (the surface touches it tangentially or runs parallel to it: no
/// gradient within the plane to follow).
/// \pre 0 <= axis < 3. \throw EvaluationError if f or grad f is not finite on the way.
bool project_to_surface_in_plane(const Sampler& f, Vec3& p, int axis, double tolerance, double max_step,
                                 Vec3* gradient = nullptr);

}  // namespace isopatch
