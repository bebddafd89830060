#pragma once
// Scalar sample types shared by the volume readers: what .npy and NRRD call them, and the decoding of
// packed samples of one type and byte order into doubles.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace isopatch::volume_io {

enum class ScalarType { Bool, Int8, Uint8, Int16, Uint16, Int32, Uint32, Int64, Uint64, Float32, Float64 };

/// Bytes per sample.
std::size_t scalar_size(ScalarType type);
/// The type of a NRRD `type:` value ("float", "unsigned short", "int16", "uint8_t", ...), or nullopt.
std::optional<ScalarType> nrrd_scalar_type(std::string_view name);
/// The type of a numpy kind and size ('f', 4), ('i', 2), ('u', 1), ('b', 1), or nullopt.
std::optional<ScalarType> numpy_scalar_type(char kind, std::size_t size);

/// `count` samples of `type` packed at `data` (which holds at least count * scalar_size(type) bytes).
std::vector<double> decode_scalars(const char* data, std::size_t count, ScalarType type, bool big_endian);

/// Reorders `samples` laid out with axis 0 fastest (NRRD, Fortran order) into C order (axis 2 fastest)
/// for a volume of `shape` (x, y, z).
std::vector<double> fastest_first_to_c_order(const std::vector<double>& samples,
                                             const std::size_t (&shape)[3]);

}  // namespace isopatch::volume_io
