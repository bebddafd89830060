#pragma once
// Internal: the header of a PLY file (Turk 1994, "The PLY Polygon File Format"): its encoding and
// the elements it declares, each with a count and typed (scalar or list) properties.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace isopatch::io {

enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

/// Bytes of one value in a binary file.
std::size_t ply_type_size(PlyType type);
bool ply_type_is_integer(PlyType type);
/// Smallest and largest value of an integer type (as doubles: every PLY integer fits exactly).
double ply_type_min(PlyType type);
double ply_type_max(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  ///< the value type (of each item, for a list)
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;  ///< the list length type (an integer type), for a list
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;

  /// The property of that name, or -1.
  int find(std::string_view property) const;
};

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;  ///< first byte after the end_header line
  std::size_t body_line = 1;    ///< line number of that byte (for messages about ASCII bodies)
};

/// Parses the header. \throw IoError naming `name` for a missing magic, format or end_header, an
/// unknown type or keyword, a property outside an element, or a repeated element or property name.
PlyHeader parse_ply_header(std::string_view bytes, const std::string& name);

}  // namespace isopatch::io
