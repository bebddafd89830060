// Object File Format (Geomview OFF): the keyword OFF, a line of counts (vertices, faces and an unused
// edge count), one vertex per line, then one face per line as `n i0 ... i(n-1)` with 0-based indices.
// '#' starts a comment. Numbers after the coordinates of a vertex or the indices of a face (colours
// in some files) must be numbers and are not kept.
#include "mesh/io_util.hpp"
#include "mesh/mesh_formats.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace isopatch::io {
namespace {

constexpr char kComment = '#';

// The first token of the next line that has one (comments and blank lines skipped).
bool seek_content(Tokens& tokens, std::string_view& first) {
  for (;;) {
    first = tokens.next_on_line(kComment);
    if (!first.empty()) return true;
    if (!tokens.next_line()) return false;
  }
}

// Remaining tokens of a line must be numbers; they are ignored (colours).
void skip_numbers(Tokens& tokens, const std::string& name) {
  for (std::string_view token = tokens.next_on_line(kComment); !token.empty();
       token = tokens.next_on_line(kComment)) {
    double ignored = 0.0;
    if (!parse_double(token, ignored)) fail_at(name, tokens.line(), "bad number " + io::quoted(token));
  }
}

std::uint64_t read_count(Tokens& tokens, std::string_view token, const char* what, const std::string& name) {
  std::uint64_t count = 0;
  if (token.empty()) fail_at(name, tokens.line(), std::string("missing ") + what + " count");
  if (!parse_uint(token, count))
    fail_at(name, tokens.line(), std::string("bad ") + what + " count " + io::quoted(token));
  return count;
}

}  // namespace

void encode_off(const Mesh& mesh, ByteSink& out) {
  out += "OFF\n# isopatch mesh\n" + std::to_string(mesh.vertex_count()) + ' ' +
         std::to_string(mesh.triangle_count()) + " 0\n";
  for (const Vec3& p : mesh.positions) {
    for (int axis = 0; axis < 3; ++axis) {
      if (axis > 0) out += ' ';
      append_number(out, p[axis]);
    }
    out += '\n';
  }
  for (const Triangle& t : mesh.triangles) {
    out += '3';
    for (std::uint32_t v : t) {
      out += ' ';
      append_number(out, static_cast<std::int64_t>(v));
    }
    out += '\n';
  }
}

Mesh decode_off(std::string_view bytes, const std::string& name) {
  Tokens tokens(bytes);
  std::string_view token;
  if (!seek_content(tokens, token) || token != "OFF") fail(name, "not an OFF file (no OFF keyword)");

  if (!seek_content(tokens, token)) fail(name, "missing vertex and face counts");
  const std::uint64_t vertex_count = read_count(tokens, token, "vertex", name);
  const std::uint64_t face_count = read_count(tokens, tokens.next_on_line(kComment), "face", name);
  if (const std::string_view edges = tokens.next_on_line(kComment); !edges.empty()) {
    read_count(tokens, edges, "edge", name);
    if (!tokens.next_on_line(kComment).empty())
      fail_at(name, tokens.line(), "too many numbers on the counts line");
  }
  tokens.next_line();

  // Never trust the counts: every number needs at least one character and one separator.
  const std::uint64_t room = tokens.remaining() + 1;
  if (vertex_count > room / 6 || face_count > room / 8 || 6 * vertex_count + 8 * face_count > room)
    fail(name, "declares " + std::to_string(vertex_count) + " vertices and " + std::to_string(face_count) +
                   " faces but only " + std::to_string(tokens.remaining()) + " bytes follow");
  if (vertex_count > std::numeric_limits<std::uint32_t>::max()) fail(name, "too many vertices");

  Mesh mesh;
  mesh.positions.reserve(vertex_count);
  for (std::uint64_t v = 0; v < vertex_count; ++v) {
    if (!seek_content(tokens, token))
      fail(name,
           "file ends after " + std::to_string(v) + " of " + std::to_string(vertex_count) + " vertices");
    Vec3 p;
    for (int axis = 0; axis < 3; ++axis) {
      if (axis > 0) token = tokens.next_on_line(kComment);
      if (token.empty())
        fail_at(name, tokens.line(), "vertex " + std::to_string(v) + " has fewer than 3 coordinates");
      if (!parse_double(token, p[axis])) fail_at(name, tokens.line(), "bad number " + io::quoted(token));
      if (!std::isfinite(p[axis]))
        fail_at(name, tokens.line(),
                "vertex " + std::to_string(v) + " coordinate " + io::quoted(token) + " is not finite");
    }
    skip_numbers(tokens, name);
    tokens.next_line();
    mesh.positions.push_back(p);
  }

  mesh.triangles.reserve(face_count);
  std::vector<std::int64_t> corners;
  for (std::uint64_t f = 0; f < face_count; ++f) {
    if (!seek_content(tokens, token))
      fail(name, "file ends after " + std::to_string(f) + " of " + std::to_string(face_count) + " faces");
    std::uint64_t n = 0;
    if (!parse_uint(token, n)) fail_at(name, tokens.line(), "bad face size " + io::quoted(token));
    if (n < 3 || n > kMaxPolygon)
      fail_at(name, tokens.line(), "face " + std::to_string(f) + " has " + std::to_string(n) + " vertices");
    corners.clear();
    for (std::uint64_t i = 0; i < n; ++i) {
      token = tokens.next_on_line(kComment);
      std::int64_t index = 0;
      if (token.empty())
        fail_at(name, tokens.line(),
                "face " + std::to_string(f) + " has fewer than " + std::to_string(n) + " indices");
      if (!parse_int(token, index)) fail_at(name, tokens.line(), "bad vertex index " + io::quoted(token));
      corners.push_back(index);
    }
    skip_numbers(tokens, name);
    if (const std::string problem = add_polygon(mesh, corners, vertex_count); !problem.empty())
      fail_at(name, tokens.line(), "face " + std::to_string(f) + " " + problem);
    tokens.next_line();
  }
  if (seek_content(tokens, token))
    fail_at(name, tokens.line(), "unexpected data after the last face: " + io::quoted(token));
  check_read_mesh(mesh, name);
  return mesh;
}

}  // namespace isopatch::io
