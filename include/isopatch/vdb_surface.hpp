#pragma once
/// \file vdb_surface.hpp
/// OpenVDB grids (.vdb files: the level sets Houdini, Blender, nTop and OpenVDB's own tools write) as
/// surfaces. A scalar grid (float or double values, axis-aligned voxels) becomes f(p) = s(p) - level,
/// where s is a tricubic B-spline over the voxel centres whose coefficients are the samples' cubic
/// quasi-interpolant: along each axis c[i] = (-v[i-1] + 8 v[i] - v[i+1]) / 6, the local filter that
/// makes the spline reproduce every cubic polynomial (so s differs from a sample of a smooth function by
/// O(h^4), h the voxel size, as the interpolating spline of a .npy volume does; Unser, Aldroubi & Eden
/// 1991 for the cubic B-spline's filters). s is C2: the meshers project onto its zero set, and its value,
/// gradient and Hessian are exact derivatives of one function. A local filter keeps the grid sparse:
/// coefficients are stored only for the grid's leaf nodes (8^3 voxels each) and the leaf positions
/// around them, so memory follows the active voxels and never the bounding box (a .npy volume's
/// interpolating filter reaches across the whole grid and needs it dense).
///
/// Outside the narrow band. A level set stores values only near its zero set; everywhere else the grid
/// holds inactive tiles and its background, +-(half width) by side. There the coefficients are those
/// values themselves, so f is constant away from the band and crosses the level nowhere else. The zero
/// set of s equals the samples' where every sample within three voxels of it (along each axis) is
/// stored: OpenVDB's default half width of 3 voxels gives that; a thinner band flattens s near the
/// surface. Inactive values must lie on the same side of the level as the voxels next to them (what a
/// level set's signed flood fill makes): the bounds that let the meshers skip empty space rely on it.
///
/// Interval bounds come from the convex-hull property of B-splines (value between the smallest and
/// largest coefficient reaching a box, each gradient component between the smallest and largest
/// difference of neighbours), from per-leaf summaries, and from the tiles' values by side.
///
/// Reading: the file's layout is checked first, and OpenVDB reads the grid's tree in a forked child
/// process (it overflows buffers on some corrupt files), which returns plain numbers through a pipe.
///
/// Refusals (one line naming the file): not an OpenVDB file, a truncated or malformed one, a grid that
/// is not float or double, a rotated, sheared or perspective transform, NaN or infinite values, more than
/// kMaxVolumeSamples stored voxels: IoError; no stored value crossing the level: NoSurfaceError; an
/// unknown or ambiguous grid name: InputError (setting "grid").

#include <isopatch/surface.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace isopatch {

/// What a .vdb file holds, grid by grid.
struct VdbGridInfo {
  std::string name;
  std::string value_type;  ///< "float", "double", "vec3s", ...
  std::string grid_class;  ///< "level set", "fog volume", "staggered", "unknown"
  std::uint64_t active_voxels = 0;
};

/// Which grid of a file, and which level of it.
struct VdbSource {
  /// The grid's name; empty: the file's only level set, else its only float or double grid.
  std::string grid;
  /// The level meshed (0: a level set's zero set).
  double level = 0.0;
  /// False: values below the level are inside (signed distances); true: values above it are (densities),
  /// f = level - s, so normals point towards lower values.
  bool inside_above = false;
};

/// True when `path` ends in .vdb (case-insensitive).
bool is_vdb_path(const std::string& path);

/// The grids of the .vdb file at `path` (names, types, classes, active voxels), in file order.
/// \throw IoError for a file that cannot be read or is not an OpenVDB file.
std::vector<VdbGridInfo> vdb_grids(const std::string& path);

/// The surface `source.level` of one grid of the .vdb file at `path` (see the file comment). Its
/// default box spans the centres of the grid's active voxels (in world coordinates). Memory: about
/// 2.5 KB per 8^3 leaf of the grid and per leaf position next to one; time proportional to the same.
/// \throw IoError, NoSurfaceError, InputError as listed in the file comment.
SurfacePtr vdb_surface(const std::string& path, const VdbSource& source = {});

/// The same from the bytes of a .vdb file held in memory; `name` stands for the file in messages.
/// \throw as vdb_surface()
SurfacePtr decode_vdb_surface(std::string_view bytes, const VdbSource& source = {},
                              const std::string& name = "<memory>");

/// Bytes a surface of vdb_surface() holds for its coefficients, tiles and summaries (0 for any other
/// surface): what "memory follows the active voxels" is measured by.
std::size_t vdb_surface_bytes(const Surface& surface);

}  // namespace isopatch
