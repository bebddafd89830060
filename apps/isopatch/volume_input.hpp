#pragma once
// `isopatch mesh VOLUME.npy|VOLUME.nrrd --level L --spacing sx,sy,sz --origin ox,oy,oz`: a sampled
// volume as the surface to mesh (its tricubic B-spline interpolant, volume_surface.hpp);
// `isopatch mesh MODEL.vdb [--grid NAME] [--level L]`: an OpenVDB grid (vdb_surface.hpp).

#include <isopatch/surface.hpp>

#include <optional>
#include <string>

namespace isopatch::cli {

struct VolumeOptions {
  std::optional<double> level;  ///< default 0
  std::string spacing;          ///< "sx,sy,sz" (or one number for all three); empty: from the file
  std::string origin;           ///< "ox,oy,oz"; empty: from the file
  bool given() const { return level || !spacing.empty() || !origin.empty(); }
};

/// The surface `level` of the volume in `path` (.npy or .nrrd), with the file's spacing and origin
/// unless overridden. \throw IoError for the file, InputError for a bad --spacing or --origin,
/// NoSurfaceError when no sample crosses the level.
SurfacePtr volume_input(const std::string& path, const VolumeOptions& options);

/// The surface --level (default 0) of the grid `grid` (empty: the file's only level set) of the .vdb
/// file at `path`. \throw InputError for --spacing or --origin (the grid's transform gives them) or an
/// unknown grid, IoError for the file, NoSurfaceError when no value crosses the level.
SurfacePtr vdb_input(const std::string& path, const VolumeOptions& options, const std::string& grid);

/// Marching cubes' cells along the longest box axis: --mc-grid, else --grid as a whole number unless the
/// input is a .vdb file (whose --grid names a grid), else 64. \throw SettingError("grid") for a --grid
/// that is not a whole number.
int marching_cubes_cells(const std::optional<std::string>& grid, const std::optional<int>& mc_grid, bool vdb);

}  // namespace isopatch::cli
