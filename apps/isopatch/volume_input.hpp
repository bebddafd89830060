#pragma once
// `isopatch mesh VOLUME.npy|VOLUME.nrrd --level L --spacing sx,sy,sz --origin ox,oy,oz`: a sampled
// volume as the surface to mesh (its tricubic B-spline interpolant, volume_surface.hpp).

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

}  // namespace isopatch::cli
