#pragma once
/// \file volume_surface.hpp
/// A sampled volume as a Surface: f(p) = s(p) - level, where s is the tricubic B-spline that
/// interpolates the samples (s equals every sample at its grid point; Unser, Aldroubi & Eden 1991,
/// "Fast B-spline transforms for continuous image representation and interpolation"), extended beyond
/// the grid by mirror symmetry about the first and last samples. s is C2, so its value, gradient and
/// Hessian are exact derivatives of one smooth function and every mesher projects onto its zero set:
/// the mesh vertices lie on the interpolated surface. Interval bounds come from the convex-hull property
/// of B-splines (the value over a box lies between the smallest and largest coefficient that reach it,
/// each gradient component between the smallest and largest coefficient differences).
///
/// Values below `level` are inside (f < 0), so normals point towards higher sample values.

#include <isopatch/surface.hpp>
#include <isopatch/volume.hpp>

#include <string>

namespace isopatch {

/// The interpolated surface s = level of `volume`; its default box is volume.extent().
/// O(samples) time and memory to set up (one tridiagonal solve per grid line and axis).
/// \throw InputError as Volume::validate(), or for a non-finite level (setting "level")
/// \throw NoSurfaceError when no sample is below `level` or none is at or above it ("no sample
///        crosses level 2 (the samples range over [0, 1])")
SurfacePtr volume_surface(Volume volume, double level, std::string name = "volume");

}  // namespace isopatch
