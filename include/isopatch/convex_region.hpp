#pragma once
/// \file convex_region.hpp
/// Convex regions, rotated frames and partitions of convex cells given by a caller: the settings that
/// mesh inside a polytope, in a rotated octree, or over the caller's own cells (Sipos & Salvi 2021,
/// sec. 2: the method works with "any convex partitioning which is made of planar cuts").

#include <isopatch/geometry.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace isopatch {

/// The half-space a x + b y + c z + d <= 0.
struct HalfSpace {
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0;
};

/// A convex polytope: the intersection of its half-spaces.
using ConvexRegion = std::vector<HalfSpace>;

/// The most planes a region (or one given cell) may have, and the most cells a caller may give.
inline constexpr std::size_t kMaxRegionPlanes = 1000;
inline constexpr std::size_t kMaxGivenCells = 100000;

/// Parses "a,b,c,d;a,b,c,d;..." (';' or line breaks between planes, blank lines and lines starting
/// with '#' ignored) into half-spaces.
/// \throw InputError naming the plane (1-based) that is not four finite numbers or has a = b = c = 0,
///        when there is no plane at all, or more than kMaxRegionPlanes.
ConvexRegion parse_region(const std::string& text);

/// Checks a region's planes: at most kMaxRegionPlanes, finite, with a normal. `setting` names the field
/// in the error.
/// \throw SettingError(setting, ...) naming the first bad plane.
void validate_region(const ConvexRegion& region, const char* setting);

/// The bounds of a bounded region, grown by 0.1% of their diagonal, or nothing when the region is
/// unbounded, i.e. reaches the faces of `far` (which stands for infinity). What a region without a box
/// covers (Settings::region).
/// \throw SettingError("region") for a bad plane (validate_region) or a region with no volume in `far`.
std::optional<Box> region_bounds(const ConvexRegion& region, const Box& far);

/// region_bounds with `far` the cube of half-side 10^4 times the planes' largest distance from the
/// origin (at least 1) about the origin: for a region with no surface box to judge it by (a formula).
std::optional<Box> region_bounds(const ConvexRegion& region);

/// The six half-spaces of `box` (unit normals out of it, lower then upper face per axis x, y, z).
ConvexRegion box_planes(const Box& box);

/// A rotated frame for the partition: azimuth about z, then elevation about the new y, then roll about
/// the new x, in degrees. Frame coordinates y map to the user's x = R y with R = Rz(az) Ry(-el) Rx(roll),
/// so the frame's x axis points at azimuth az and elevation el.
struct Frame {
  double azimuth = 0.0;
  double elevation = 0.0;
  double roll = 0.0;

  /// R: its columns are the frame's axes in the user's coordinates.
  Mat3 rotation() const;
};

/// Parses "AZ,EL,ROLL" (degrees). \throw InputError unless three finite numbers.
Frame parse_frame(const std::string& text);

}  // namespace isopatch
