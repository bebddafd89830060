#pragma once
// Surface colour for the renderer: the Blinn-Phong formula of render.hpp and the
// isophote stripes.

#include <isopatch/mesh.hpp>
#include <isopatch/render.hpp>

#include <vector>

namespace isopatch::render {

/// The colour of render.hpp's Lighting formula for the Shaded mode, for a unit normal in camera
/// coordinates. Not clamped.
Colour shaded_colour(const Colour& base, const Vec3& normal, const Lighting& lighting);

/// The colour of render.hpp's Lighting formula for the field modes. Not clamped.
Colour field_colour(const Colour& base, const Vec3& normal, const Lighting& lighting);

/// The stripe index, 0..stripes-1, of the angle between the unit normal and the unit light direction:
/// stripe k covers angles in [k, k + 1) * 180 / stripes degrees (the last stripe includes 180).
int isophote_stripe(const Vec3& normal, const Vec3& light, int stripes);

/// Brightness factor of the dark isophote stripes (the light ones are the plain lit surface).
inline constexpr double kDarkStripe = 0.2;

/// A colour clamped to [0, 1] per channel and rounded to 8 bits.
Rgb to_rgb8(const Colour& colour);

}  // namespace isopatch::render
