// PLY bodies (Turk 1994), ASCII or binary of either byte order, read element by element in the order
// the header declares them. The vertex element gives positions (x, y, z) and one float attribute per
// other scalar property; the face element gives polygons (vertex_indices or vertex_index), fan-
// triangulated; every other element and property is skipped. Before anything is allocated, the
// declared counts are checked against the bytes the body actually has.
#include "mesh/io_util.hpp"
#include "mesh/mesh_formats.hpp"
#include "mesh/ply_header.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace isopatch::io {
namespace {

// Where the reader is, for messages: "<file>: face 12 refers to vertex 99 but there are 40 vertices".
struct Place {
  const std::string& name;
  const PlyElement* element = nullptr;
  std::uint64_t item = 0;

  [[noreturn]] void fail(const std::string& problem) const {
    io::fail(name, element->name + " " + std::to_string(item) + " " + problem);
  }
};

class BinarySource {
 public:
  BinarySource(std::string_view body, bool big_endian, Place& place)
      : body_(body), big_endian_(big_endian), place_(place) {}

  double read(PlyType type) {
    const std::size_t size = ply_type_size(type);
    if (body_.size() - pos_ < size) place_.fail("is cut short by the end of the file");
    const char* p = body_.data() + pos_;
    pos_ += size;
    switch (type) {
      case PlyType::Int8:
        return load_scalar<std::int8_t>(p, big_endian_);
      case PlyType::UInt8:
        return load_scalar<std::uint8_t>(p, big_endian_);
      case PlyType::Int16:
        return load_scalar<std::int16_t>(p, big_endian_);
      case PlyType::UInt16:
        return load_scalar<std::uint16_t>(p, big_endian_);
      case PlyType::Int32:
        return load_scalar<std::int32_t>(p, big_endian_);
      case PlyType::UInt32:
        return load_scalar<std::uint32_t>(p, big_endian_);
      case PlyType::Float32:
        return static_cast<double>(load_scalar<float>(p, big_endian_));
      case PlyType::Float64:
        return load_scalar<double>(p, big_endian_);
    }
    return 0.0;
  }

  void skip(PlyType type, std::uint64_t count) {
    const std::size_t size = ply_type_size(type);
    if (count > (body_.size() - pos_) / size) place_.fail("has a list that runs past the end of the file");
    pos_ += static_cast<std::size_t>(count) * size;
  }

  /// Every value occupies its size in bytes.
  static std::uint64_t min_bytes(PlyType type) { return ply_type_size(type); }
  std::size_t remaining() const { return body_.size() - pos_; }
  /// Anything left but whitespace is an error (a header that under-declares its counts).
  bool only_padding_left() const {
    return body_.find_first_not_of(" \t\r\n", pos_) == std::string_view::npos;
  }

 private:
  std::string_view body_;
  std::size_t pos_ = 0;
  bool big_endian_;
  Place& place_;
};

class AsciiSource {
 public:
  AsciiSource(std::string_view body, std::size_t first_line, Place& place)
      : tokens_(body, first_line), place_(place) {}

  double read(PlyType type) {
    const std::string_view token = tokens_.next();
    if (token.empty()) place_.fail("is cut short by the end of the file");
    if (ply_type_is_integer(type)) {
      std::int64_t value = 0;
      if (!parse_int(token, value))
        place_.fail("has a bad integer " + io::quoted(token) + " on line " + std::to_string(tokens_.line()));
      const auto v = static_cast<double>(value);
      if (v < ply_type_min(type) || v > ply_type_max(type))
        place_.fail("has " + io::quoted(token) + " on line " + std::to_string(tokens_.line()) +
                    ", out of range for its type");
      return v;
    }
    double value = 0.0;
    if (!parse_double(token, value))
      place_.fail("has a bad number " + io::quoted(token) + " on line " + std::to_string(tokens_.line()));
    return type == PlyType::Float32 ? static_cast<double>(static_cast<float>(value)) : value;
  }

  void skip(PlyType type, std::uint64_t count) {
    for (std::uint64_t i = 0; i < count; ++i) read(type);
  }

  /// Every number needs a character and a separator (but the last one).
  static std::uint64_t min_bytes(PlyType) { return 2; }
  std::size_t remaining() const { return tokens_.remaining() + 1; }
  bool only_padding_left() { return tokens_.at_end(); }

 private:
  Tokens tokens_;
  Place& place_;
};

// Which property of the vertex element goes where.
struct VertexLayout {
  int xyz[3] = {-1, -1, -1};
  std::vector<int> slot;  // per property: 0..2 = coordinate, 3 + k = attribute k, -1 = skipped list
};

VertexLayout vertex_layout(const PlyElement& vertex, Mesh& mesh, const std::string& name) {
  VertexLayout layout;
  layout.slot.assign(vertex.properties.size(), -1);
  const char* axes[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    layout.xyz[axis] = vertex.find(axes[axis]);
    if (layout.xyz[axis] < 0) fail(name, std::string("vertex element has no '") + axes[axis] + "' property");
    if (vertex.properties[layout.xyz[axis]].is_list)
      fail(name, std::string("vertex '") + axes[axis] + "' is a list");
    layout.slot[layout.xyz[axis]] = axis;
  }
  for (std::size_t p = 0; p < vertex.properties.size(); ++p) {
    const PlyProperty& property = vertex.properties[p];
    if (layout.slot[p] >= 0 || property.is_list) continue;
    layout.slot[p] = 3 + static_cast<int>(mesh.attributes.size());
    try {
      mesh.set_attribute(property.name, std::vector<float>(mesh.positions.size()));
    } catch (const InputError&) {
      fail(name, "vertex property " + io::quoted(property.name) + " is not a valid attribute name");
    }
  }
  return layout;
}

int face_list(const PlyElement& face, const std::string& name) {
  int list = face.find("vertex_indices");
  if (list < 0) list = face.find("vertex_index");
  if (list < 0) fail(name, "face element has no 'vertex_indices' property");
  if (!face.properties[list].is_list) fail(name, "face 'vertex_indices' is not a list");
  return list;
}

// Checks that the body can hold every declared item at its smallest size.
template <class Source>
void check_counts(const PlyHeader& header, const Source& source, const std::string& name) {
  const std::uint64_t room = source.remaining();
  std::uint64_t needed = 0;
  for (const PlyElement& element : header.elements) {
    std::uint64_t item = 0;
    for (const PlyProperty& p : element.properties)
      item += Source::min_bytes(p.is_list ? p.count_type : p.type);
    if (item == 0) continue;
    if (element.count > room / item || needed + element.count * item > room)
      fail(name, "element '" + element.name + "' declares " + std::to_string(element.count) +
                     " items but the data after the header cannot hold them");
    needed += element.count * item;
  }
}

template <class Source>
Mesh read_body(const PlyHeader& header, Source& source, Place& place) {
  const std::string& name = place.name;
  check_counts(header, source, name);
  const PlyElement* vertex = nullptr;
  for (const PlyElement& e : header.elements)
    if (e.name == "vertex") vertex = &e;
  if (!vertex) fail(name, "has no 'vertex' element");
  // Without properties a vertex takes no bytes, so check_counts() cannot bound its count: refuse it
  // before anything is allocated (x, y and z are required anyway).
  if (vertex->properties.empty()) fail(name, "the 'vertex' element has no properties (x, y, z are required)");
  if (vertex->count > std::numeric_limits<std::uint32_t>::max()) fail(name, "too many vertices");
  const auto vertex_count = static_cast<std::size_t>(vertex->count);

  Mesh mesh;
  mesh.positions.resize(vertex_count);
  const VertexLayout layout = vertex_layout(*vertex, mesh, name);
  std::vector<std::int64_t> corners;

  for (const PlyElement& element : header.elements) {
    place.element = &element;
    const bool is_vertex = &element == vertex;
    const int list = element.name == "face" ? face_list(element, name) : -1;
    if (list >= 0) mesh.triangles.reserve(element.count);
    if (element.properties.empty()) continue;
    for (std::uint64_t item = 0; item < element.count; ++item) {
      place.item = item;
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (!property.is_list) {
          const double value = source.read(property.type);
          if (!is_vertex) continue;
          const int slot = layout.slot[p];
          if (slot < 3) {
            if (!std::isfinite(value))
              place.fail("has a coordinate " + property.name + " that is not finite");
            mesh.positions[item][slot] = value;
          } else {
            mesh.attributes[slot - 3].values[item] = static_cast<float>(value);
          }
          continue;
        }
        const double count = source.read(property.count_type);
        if (count < 0) place.fail("has a negative list length");
        if (static_cast<int>(p) != list) {
          source.skip(property.type, static_cast<std::uint64_t>(count));
          continue;
        }
        if (count < 3 || count > kMaxPolygon)
          place.fail("has " + std::to_string(static_cast<std::int64_t>(count)) + " vertices (3 to " +
                     std::to_string(kMaxPolygon) + " allowed)");
        corners.clear();
        for (int i = 0; i < static_cast<int>(count); ++i) {
          const double index = source.read(property.type);
          if (index != std::floor(index))
            place.fail("has a vertex index " + std::to_string(index) + " that is not an integer");
          corners.push_back(
              static_cast<std::int64_t>(std::clamp(index, -1e15, 1e15)));  // any PLY integer fits
        }
        if (const std::string problem = add_polygon(mesh, corners, vertex_count); !problem.empty())
          place.fail(problem);
      }
    }
  }
  if (!source.only_padding_left()) fail(name, "unexpected data after the last element");
  return mesh;
}

void append_header(ByteSink& out, const Mesh& mesh, bool binary) {
  out += "ply\nformat ";
  out += binary ? "binary_little_endian" : "ascii";
  out += " 1.0\ncomment isopatch mesh\nelement vertex " + std::to_string(mesh.vertex_count()) +
         "\nproperty double x\nproperty double y\nproperty double z\n";
  for (const VertexAttribute& a : mesh.attributes) out += "property float " + a.name + "\n";
  out += "element face " + std::to_string(mesh.triangle_count()) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

void check_writable(const Mesh& mesh) {
  if (mesh.vertex_count() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw InputError("mesh has too many vertices for PLY int indices");
  for (std::size_t i = 0; i < mesh.attributes.size(); ++i) {
    const std::string& n = mesh.attributes[i].name;
    Mesh probe;
    probe.set_attribute(n, {});  // throws InputError for a name that is not an identifier
    if (n == "x" || n == "y" || n == "z")
      throw InputError("attribute name '" + n + "' collides with a coordinate");
    for (std::size_t j = 0; j < i; ++j)
      if (mesh.attributes[j].name == n) throw InputError("attribute name '" + n + "' appears twice");
  }
}

}  // namespace

void encode_ply(const Mesh& mesh, bool binary, ByteSink& out) {
  check_writable(mesh);
  append_header(out, mesh, binary);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      if (binary) {
        append_le(out, mesh.positions[v][axis]);
      } else {
        if (axis > 0) out += ' ';
        append_number(out, mesh.positions[v][axis]);
      }
    }
    for (const VertexAttribute& a : mesh.attributes) {
      if (binary) {
        append_le(out, a.values[v]);
      } else {
        out += ' ';
        append_number(out, a.values[v]);
      }
    }
    if (!binary) out += '\n';
  }
  for (const Triangle& t : mesh.triangles) {
    if (binary) {
      append_le(out, std::uint8_t{3});
      for (std::uint32_t v : t) append_le(out, static_cast<std::int32_t>(v));
    } else {
      out += '3';
      for (std::uint32_t v : t) {
        out += ' ';
        append_number(out, static_cast<std::int64_t>(v));
      }
      out += '\n';
    }
  }
}

Mesh decode_ply(std::string_view bytes, const std::string& name) {
  const PlyHeader header = parse_ply_header(bytes, name);
  const std::string_view body = bytes.substr(header.body_offset);
  Place place{name};
  Mesh mesh;
  if (header.encoding == PlyEncoding::Ascii) {
    AsciiSource source(body, header.body_line, place);
    mesh = read_body(header, source, place);
  } else {
    BinarySource source(body, header.encoding == PlyEncoding::BinaryBigEndian, place);
    mesh = read_body(header, source, place);
  }
  check_read_mesh(mesh, name);
  return mesh;
}

}  // namespace isopatch::io
