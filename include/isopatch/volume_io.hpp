#pragma once
/// \file volume_io.hpp
/// Reading sampled volumes: numpy's .npy (format versions 1 to 3; little- or big-endian signed and
/// unsigned integers of 1 to 8 bytes, float32, float64 and bool; C or Fortran order; 3 dimensions)
/// and NRRD (.nrrd with the data attached; encodings raw and gzip; the same scalar types; spacing
/// from `spacings` or axis-aligned `space directions`, origin from `space origin`).
///
/// Axis order: .npy axes 0, 1, 2 are x, y, z (as numpy and scikit-image index); an NRRD file lists
/// its fastest axis first, and that axis is x. Samples become doubles. A .npy file carries no spacing
/// or origin: they are 1 and 0.
///
/// Readers never trust a header: the shape is checked against kMaxVolumeSamples and against the bytes
/// the file holds before anything is allocated; any malformed, truncated or oversized input throws an
/// IoError whose one-line message names the file and the problem. The volume returned passes
/// Volume::validate() (so NaN or infinite samples are an IoError too).

#include <isopatch/volume.hpp>

#include <string>
#include <string_view>

namespace isopatch {

enum class VolumeFormat { Npy, Nrrd };

/// True when `path` ends in .npy or .nrrd (case-insensitive): what the command line reads as a volume.
bool is_volume_path(const std::string& path);
/// The format for a path from its extension. \throw IoError for any other extension.
VolumeFormat volume_format_from_path(const std::string& path);
/// Reads the volume in `path`, the format from its extension. \throw IoError as above.
Volume read_volume(const std::string& path);
/// Parses bytes as read_volume would parse a file; `name` stands for the file in error messages.
/// \throw IoError as above.
Volume decode_volume(std::string_view bytes, VolumeFormat format, const std::string& name = "<memory>");

}  // namespace isopatch
