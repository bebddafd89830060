#pragma once
/// \file composite_checks.hpp
/// Checks of the conventions of composite.hpp that every builder runs on what it built.

#include "composite_model/composite.hpp"

#include <cstddef>

namespace isopatch {

/// Checks that the composite is closed: every patch has n >= 3 sides, as many corner directions (unit,
/// finite) and a surface; side k ends exactly where side k+1 starts; every curve is used by exactly
/// two sides, in opposite directions.
/// \throw InputError naming the first patch or curve that breaks a rule.
void check_composite_closed(const Composite& composite);

/// Checks what meshing a composite needs (a composite may be open): 3..12 sides per patch with as many
/// finite non-zero corner directions, curve ids in range, side k ending exactly where side k + 1 starts,
/// every curve used at most twice and, when twice, in opposite directions.
/// \throw InputError naming the patch or curve otherwise.
void check_composite(const Composite& composite);

/// The largest |f| / |grad f| of the patch's own function over `samples` interior points of each of
/// its boundary curves: how far (to first order) the curves lie from the patch.
double boundary_residual(const Composite& composite, std::size_t patch, int samples = 16);

/// The box of the composite's curves (control points hold every arc) and of `extra` points, grown by
/// `margin` times its diagonal on every side.
Box curves_box(const std::vector<ConicArc>& curves, const std::vector<Vec3>& extra, double margin);

}  // namespace isopatch
