#pragma once
/// \file volume_surface.hpp
/// A sampled volume as a Surface: f(p) = s(p) - level, where s is the tricubic B-spline that
/// interpolates the samples (s equals every sample at its grid point; Unser, Aldroubi & Eden 1991,
/// "Fast B-spline transforms for continuous image representation and interpolation"), extended beyond
/// the grid by mirror symmetry about the first and last samples. s is C2, so its value, gradient and
/// Hessian are exact derivatives of one smooth function and every mesher projects onto its zero set:
/// the mesh vertices lie on the interpolated surface. Interval bounds come from the convex-hull property
/// of B-splines (the value over a box lies between the smallest and largest coefficient that reach it,
/// each gradient component between the smallest and largest coefficient differences); over large
/// boxes they come from the extremes of 8^3-coefficient bricks, summarised once on the first bound asked
/// for (the very values a scan finds, in time proportional to the bricks).
///
/// Values below `level` are inside (f < 0), so normals point towards higher sample values.

#include <isopatch/surface.hpp>
#include <isopatch/volume.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <string>

namespace isopatch {

/// The interpolated surface s = level of `volume`; its default box is volume.extent().
/// O(samples) time and memory to set up (one tridiagonal solve per grid line and axis).
/// \throw InputError as Volume::validate(), or for a non-finite level (setting "level")
/// \throw NoSurfaceError when no sample is below `level` or none is at or above it ("no sample
///        crosses level 2 (the samples range over [0, 1])")
SurfacePtr volume_surface(Volume volume, double level, std::string name = "volume");

/// Samples of halo on each side of a window of a volume that make interpolating_coefficients() of the
/// window, on the window's own samples, equal to the whole volume's to rounding. The coefficient at i
/// depends on the sample at i + d through a factor that decays as z^|d|, z = 2 - sqrt(3) = 0.268
/// (the pole of the cubic B-spline's inverse filter; Unser et al. 1991), so a wrong boundary 32 samples
/// away moves it by at most about 0.268^32 = 5e-19 of the samples' size.
inline constexpr std::size_t kPrefilterHalo = 32;

/// The most coefficients mapped_volume_surface() accepts (2^36: 512 GiB of doubles).
inline constexpr std::size_t kMaxMappedSamples = std::size_t{1} << 36;

/// Replaces `samples` (C order, `shape`) in place by the coefficients of the tricubic B-spline that
/// interpolates them with the mirror boundary: what volume_surface() computes. O(samples) time, one
/// tridiagonal solve per grid line and axis. A window of a volume read with kPrefilterHalo more samples
/// on every side that is not a face of the volume gives its own samples' coefficients to rounding.
/// 	hrow InputError (setting "volume") when a side is below 2 or samples.size() is not their product.
void interpolating_coefficients(std::span<double> samples, const std::array<std::size_t, 3>& shape);

/// The surface s = level of B-spline coefficients stored in a .npy file (little-endian float64 in C
/// order, 3 dimensions: interpolating_coefficients() of a whole volume, or of its windows with
/// kPrefilterHalo), with the sample at index (i, j, k) at origin + (i, j, k) * spacing. The file is
/// mapped, not read: a process touches only the pages of the coefficients it evaluates, so volumes
/// larger than memory can be meshed piece by piece. Values, derivatives and bounds are those of
/// volume_surface() on the same coefficients; its default box is the grid's extent. It does not check
/// that the volume crosses `level` (that needs every sample; the caller knows their range). The file
/// must not change while the surface lives.
/// 	hrow IoError("<path>: ...") for a file that cannot be mapped, is not such a .npy, has a side
///        below 2 or more than kMaxMappedSamples coefficients, or holds more or fewer bytes than its
///        header says
/// 	hrow InputError for a spacing, origin or level that volume_surface() refuses
SurfacePtr mapped_volume_surface(const std::string& path, const Vec3& spacing, const Vec3& origin,
                                 double level, std::string name = "volume");

}  // namespace isopatch
