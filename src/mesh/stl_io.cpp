// STL: a soup of triangles with float corners and a facet normal. Binary layout: an 80-byte header,
// a uint32 triangle count, then 50 bytes per triangle (normal, three corners, a uint16 attribute),
// all little-endian. ASCII STL (`solid ... facet normal ... outer loop vertex ... endsolid`) is read
// too. Corners with bit-identical float coordinates are merged, so a closed mesh written by
// encode_stl is indexed (and closed) again after reading; the stored normal is ignored.
#include "mesh/io_util.hpp"
#include "mesh/mesh_formats.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <unordered_map>

namespace isopatch::io {
namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kTriangleBytes = 50;

// Indexes corners by the bits of their float coordinates.
class CornerMerger {
 public:
  explicit CornerMerger(Mesh& mesh, std::size_t expected) : mesh_(mesh) { index_.reserve(expected); }

  std::int64_t add(const std::array<float, 3>& p) {
    const Key key{std::bit_cast<std::uint32_t>(p[0]), std::bit_cast<std::uint32_t>(p[1]),
                  std::bit_cast<std::uint32_t>(p[2])};
    const auto [it, inserted] = index_.try_emplace(key, static_cast<std::uint32_t>(mesh_.positions.size()));
    if (inserted) mesh_.positions.emplace_back(p[0], p[1], p[2]);
    return it->second;
  }

 private:
  using Key = std::array<std::uint32_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k[0];
      h = h * 0x9E3779B97F4A7C15ull ^ k[1];
      h = h * 0x9E3779B97F4A7C15ull ^ k[2];
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };
  Mesh& mesh_;
  std::unordered_map<Key, std::uint32_t, KeyHash> index_;
};

void add_facet(Mesh& mesh, CornerMerger& merger, const std::array<std::array<float, 3>, 3>& corners,
               std::size_t facet, const std::string& name) {
  std::array<std::int64_t, 3> indices{};
  for (int c = 0; c < 3; ++c) {
    for (float x : corners[c])
      if (!std::isfinite(x)) fail(name, "triangle " + std::to_string(facet) + " has a non-finite coordinate");
    indices[c] = merger.add(corners[c]);
  }
  if (const std::string problem = add_polygon(mesh, indices, mesh.positions.size()); !problem.empty())
    fail(name, "triangle " + std::to_string(facet) + " " + problem);
}

Mesh decode_binary(std::string_view bytes, std::uint32_t count, const std::string& name) {
  Mesh mesh;
  mesh.triangles.reserve(count);
  CornerMerger merger(mesh, count / 2 + 3);
  const char* p = bytes.data() + kHeaderBytes + 4;
  for (std::uint32_t t = 0; t < count; ++t, p += kTriangleBytes) {
    std::array<std::array<float, 3>, 3> corners;
    for (int c = 0; c < 3; ++c)
      for (int axis = 0; axis < 3; ++axis)
        corners[c][axis] = load_scalar<float>(p + 12 * (c + 1) + 4 * axis, false);
    add_facet(mesh, merger, corners, t, name);
  }
  return mesh;
}

bool parse_float(std::string_view token, float& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return false;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, out, std::chars_format::general);
  return ec == std::errc{} && ptr == end;
}

void expect(Tokens& tokens, std::string_view word, const std::string& name) {
  const std::string_view token = tokens.next();
  if (token != word) {
    if (token.empty()) fail(name, "file ends where '" + std::string(word) + "' was expected");
    fail_at(name, tokens.line(), "expected '" + std::string(word) + "' but found " + io::quoted(token));
  }
}

float read_float(Tokens& tokens, const std::string& name) {
  const std::string_view token = tokens.next();
  float value = 0.0f;
  if (token.empty()) fail(name, "file ends inside a facet");
  if (!parse_float(token, value)) fail_at(name, tokens.line(), "bad number " + io::quoted(token));
  return value;
}

Mesh decode_ascii(std::string_view bytes, const std::string& name) {
  Mesh mesh;
  CornerMerger merger(mesh, 0);
  Tokens tokens(bytes);
  expect(tokens, "solid", name);
  tokens.next_line();  // the solid's name
  std::size_t facet = 0;
  for (;;) {
    const std::string_view token = tokens.next();
    if (token.empty()) fail(name, "file ends without 'endsolid'");
    if (token == "endsolid") {
      tokens.next_line();
      if (tokens.at_end()) break;
      expect(tokens, "solid", name);  // several solids in one file
      tokens.next_line();
      continue;
    }
    if (token != "facet") fail_at(name, tokens.line(), "expected 'facet' but found " + io::quoted(token));
    expect(tokens, "normal", name);
    for (int axis = 0; axis < 3; ++axis) read_float(tokens, name);
    expect(tokens, "outer", name);
    expect(tokens, "loop", name);
    std::array<std::array<float, 3>, 3> corners;
    for (auto& corner : corners) {
      expect(tokens, "vertex", name);
      for (float& x : corner) x = read_float(tokens, name);
    }
    expect(tokens, "endloop", name);
    expect(tokens, "endfacet", name);
    add_facet(mesh, merger, corners, facet++, name);
  }
  return mesh;
}

}  // namespace

void encode_stl(const Mesh& mesh, ByteSink& out) {
  if (mesh.triangle_count() > std::numeric_limits<std::uint32_t>::max())
    throw InputError("mesh has too many triangles for STL");
  std::string header = "isopatch binary STL";
  header.resize(kHeaderBytes, ' ');
  out += header;
  append_le(out, static_cast<std::uint32_t>(mesh.triangle_count()));
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.positions[t[0]];
    const Vec3& b = mesh.positions[t[1]];
    const Vec3& c = mesh.positions[t[2]];
    Vec3 normal = (b - a).cross(c - a);
    const double length = normal.norm();
    normal = length > 0.0 && std::isfinite(length) ? Vec3(normal / length) : Vec3::Zero();
    for (int axis = 0; axis < 3; ++axis) append_le(out, static_cast<float>(normal[axis]));
    for (std::uint32_t v : t)
      for (int axis = 0; axis < 3; ++axis) append_le(out, static_cast<float>(mesh.positions[v][axis]));
    append_le(out, std::uint16_t{0});
  }
}

Mesh decode_stl(std::string_view bytes, const std::string& name) {
  Mesh mesh;
  const bool solid = bytes.starts_with("solid");
  bool binary = false;
  if (bytes.size() >= kHeaderBytes + 4) {
    const auto count = load_scalar<std::uint32_t>(bytes.data() + kHeaderBytes, false);
    const std::uint64_t needed = kHeaderBytes + 4 + std::uint64_t{kTriangleBytes} * count;
    if (needed == bytes.size()) {
      binary = true;
      mesh = decode_binary(bytes, count, name);
    } else if (!solid) {
      fail(name, "binary STL declares " + std::to_string(count) + " triangles (" + std::to_string(needed) +
                     " bytes) but the file has " + std::to_string(bytes.size()) + " bytes");
    }
  } else if (!solid) {
    fail(name, "too short for a binary STL (" + std::to_string(bytes.size()) + " bytes) and not ASCII STL");
  }
  if (!binary) mesh = decode_ascii(bytes, name);
  check_read_mesh(mesh, name);
  return mesh;
}

}  // namespace isopatch::io
