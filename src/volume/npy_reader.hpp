#pragma once
// The .npy reader (numpy's format, versions 1 to 3) behind decode_volume (volume_io.hpp), and the
// header's layout for readers that map the data instead of copying it.

#include <isopatch/volume.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "volume/scalar_decode.hpp"

namespace isopatch::volume_io {

/// What a .npy file's header says about its 3-dimensional array, checked against the file's size.
struct NpyLayout {
  std::array<std::size_t, 3> shape{};
  std::size_t count = 0;  ///< shape[0] * shape[1] * shape[2]
  std::string descr;      ///< numpy's dtype string, e.g. "<f8"
  ScalarType type = ScalarType::Float64;
  bool big_endian = false;
  bool fortran_order = false;
  std::size_t data_offset = 0;  ///< where the packed samples start
};

/// The layout of the .npy file whose bytes are `bytes` (the whole file: its size is checked against
/// the header's shape and type); at most `max_samples` samples.
/// \throw IoError("<name>: ...") for a missing magic, an unsupported version or dtype, a malformed
///        header, other than 3 dimensions, an empty or oversized shape, or a size that disagrees.
NpyLayout read_npy_layout(std::string_view bytes, const std::string& name, std::size_t max_samples);

/// A 3-dimensional array of a scalar type (volume_io.hpp); spacing 1 and origin 0.
/// \throw IoError("<name>: ...") for anything else.
Volume decode_npy(std::string_view bytes, const std::string& name);

}  // namespace isopatch::volume_io
