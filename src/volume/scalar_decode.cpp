// Scalar sample types of the volume readers (scalar_decode.hpp).
#include "volume/scalar_decode.hpp"

#include <cstdint>

#include "mesh/io_util.hpp"

namespace isopatch::volume_io {

std::size_t scalar_size(ScalarType type) {
  switch (type) {
    case ScalarType::Bool:
    case ScalarType::Int8:
    case ScalarType::Uint8:
      return 1;
    case ScalarType::Int16:
    case ScalarType::Uint16:
      return 2;
    case ScalarType::Int32:
    case ScalarType::Uint32:
    case ScalarType::Float32:
      return 4;
    case ScalarType::Int64:
    case ScalarType::Uint64:
    case ScalarType::Float64:
      return 8;
  }
  return 1;
}

std::optional<ScalarType> nrrd_scalar_type(std::string_view name) {
  struct Entry {
    std::string_view name;
    ScalarType type;
  };
  // The spellings of the NRRD format's `type` field.
  static constexpr Entry kNames[] = {
      {"signed char", ScalarType::Int8},
      {"int8", ScalarType::Int8},
      {"int8_t", ScalarType::Int8},
      {"uchar", ScalarType::Uint8},
      {"unsigned char", ScalarType::Uint8},
      {"uint8", ScalarType::Uint8},
      {"uint8_t", ScalarType::Uint8},
      {"short", ScalarType::Int16},
      {"short int", ScalarType::Int16},
      {"signed short", ScalarType::Int16},
      {"signed short int", ScalarType::Int16},
      {"int16", ScalarType::Int16},
      {"int16_t", ScalarType::Int16},
      {"ushort", ScalarType::Uint16},
      {"unsigned short", ScalarType::Uint16},
      {"unsigned short int", ScalarType::Uint16},
      {"uint16", ScalarType::Uint16},
      {"uint16_t", ScalarType::Uint16},
      {"int", ScalarType::Int32},
      {"signed int", ScalarType::Int32},
      {"int32", ScalarType::Int32},
      {"int32_t", ScalarType::Int32},
      {"uint", ScalarType::Uint32},
      {"unsigned int", ScalarType::Uint32},
      {"uint32", ScalarType::Uint32},
      {"uint32_t", ScalarType::Uint32},
      {"longlong", ScalarType::Int64},
      {"long long", ScalarType::Int64},
      {"long long int", ScalarType::Int64},
      {"signed long long", ScalarType::Int64},
      {"signed long long int", ScalarType::Int64},
      {"int64", ScalarType::Int64},
      {"int64_t", ScalarType::Int64},
      {"ulonglong", ScalarType::Uint64},
      {"unsigned long long", ScalarType::Uint64},
      {"unsigned long long int", ScalarType::Uint64},
      {"uint64", ScalarType::Uint64},
      {"uint64_t", ScalarType::Uint64},
      {"float", ScalarType::Float32},
      {"double", ScalarType::Float64},
  };
  for (const Entry& e : kNames)
    if (e.name == name) return e.type;
  return std::nullopt;
}

std::optional<ScalarType> numpy_scalar_type(char kind, std::size_t size) {
  switch (kind) {
    case 'b':
      if (size == 1) return ScalarType::Bool;
      break;
    case 'i':
      if (size == 1) return ScalarType::Int8;
      if (size == 2) return ScalarType::Int16;
      if (size == 4) return ScalarType::Int32;
      if (size == 8) return ScalarType::Int64;
      break;
    case 'u':
      if (size == 1) return ScalarType::Uint8;
      if (size == 2) return ScalarType::Uint16;
      if (size == 4) return ScalarType::Uint32;
      if (size == 8) return ScalarType::Uint64;
      break;
    case 'f':
      if (size == 4) return ScalarType::Float32;
      if (size == 8) return ScalarType::Float64;
      break;
    default:
      break;
  }
  return std::nullopt;
}

namespace {

template <class T>
void decode_as(const char* data, std::size_t count, bool big_endian, std::vector<double>& out) {
  for (std::size_t n = 0; n < count; ++n)
    out[n] = static_cast<double>(io::load_scalar<T>(data + n * sizeof(T), big_endian));
}

}  // namespace

std::vector<double> decode_scalars(const char* data, std::size_t count, ScalarType type, bool big_endian) {
  std::vector<double> out(count);
  switch (type) {
    case ScalarType::Bool:
      for (std::size_t n = 0; n < count; ++n) out[n] = data[n] != 0 ? 1.0 : 0.0;
      break;
    case ScalarType::Int8:
      decode_as<std::int8_t>(data, count, big_endian, out);
      break;
    case ScalarType::Uint8:
      decode_as<std::uint8_t>(data, count, big_endian, out);
      break;
    case ScalarType::Int16:
      decode_as<std::int16_t>(data, count, big_endian, out);
      break;
    case ScalarType::Uint16:
      decode_as<std::uint16_t>(data, count, big_endian, out);
      break;
    case ScalarType::Int32:
      decode_as<std::int32_t>(data, count, big_endian, out);
      break;
    case ScalarType::Uint32:
      decode_as<std::uint32_t>(data, count, big_endian, out);
      break;
    case ScalarType::Int64:
      decode_as<std::int64_t>(data, count, big_endian, out);
      break;
    case ScalarType::Uint64:
      decode_as<std::uint64_t>(data, count, big_endian, out);
      break;
    case ScalarType::Float32:
      decode_as<float>(data, count, big_endian, out);
      break;
    case ScalarType::Float64:
      decode_as<double>(data, count, big_endian, out);
      break;
  }
  return out;
}

std::vector<double> fastest_first_to_c_order(const std::vector<double>& samples,
                                             const std::size_t (&shape)[3]) {
  std::vector<double> out(samples.size());
  const std::size_t nx = shape[0], ny = shape[1], nz = shape[2];
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) out[(i * ny + j) * nz + k] = samples[i + nx * (j + ny * k)];
  return out;
}

}  // namespace isopatch::volume_io
