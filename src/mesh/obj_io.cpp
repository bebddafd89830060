// Wavefront OBJ: `v x y z` and `f a b c ...` lines. Only geometry is kept: texture coordinates,
// normals, groups, materials and the other statements of the OBJ specification are skipped, since a
// Mesh has no place for them; a line that is no OBJ statement at all is an error.
// Face indices are 1-based or, when negative, relative to the vertices defined so far (the OBJ rule);
// a face may only refer to vertices defined before it.
#include "mesh/io_util.hpp"
#include "mesh/mesh_formats.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace isopatch::io {
namespace {

// Statements of the OBJ specification (geometry, grouping, display and free-form), all skipped but
// v and f. Anything else is not OBJ, which catches text or binary data given by mistake.
constexpr std::string_view kStatements[] = {
    "vt",     "vn",         "vp",        "l",      "p",     "g",    "o",    "s",     "mg",       "usemtl",
    "mtllib", "usemap",     "maplib",    "cstype", "deg",   "bmat", "step", "curv",  "curv2",    "surf",
    "parm",   "trim",       "hole",      "scrv",   "sp",    "end",  "con",  "bevel", "c_interp", "d_interp",
    "lod",    "shadow_obj", "trace_obj", "ctech",  "stech", "call", "csh",
};

bool is_statement(std::string_view word) {
  for (std::string_view s : kStatements)
    if (s == word) return true;
  return false;
}

// `a`, `a/b`, `a//c` or `a/b/c`: returns the vertex index a; b and c must be integers when present.
bool parse_corner(std::string_view token, std::int64_t& vertex) {
  const std::size_t slash = token.find('/');
  if (!parse_int(token.substr(0, slash), vertex)) return false;
  if (slash == std::string_view::npos) return true;
  std::string_view rest = token.substr(slash + 1);
  for (int part = 0; part < 2; ++part) {
    const std::size_t next = rest.find('/');
    std::int64_t ignored = 0;
    const std::string_view field = rest.substr(0, next);
    if (!field.empty() && !parse_int(field, ignored)) return false;
    if (next == std::string_view::npos) return true;
    if (part == 1) return false;  // a third slash
    rest = rest.substr(next + 1);
  }
  return true;
}

void read_vertex(Tokens& tokens, Mesh& mesh, const std::string& name) {
  Vec3 p;
  for (int axis = 0; axis < 3; ++axis) {
    const std::string_view token = tokens.next_on_line('#');
    if (token.empty()) fail_at(name, tokens.line(), "vertex has fewer than 3 coordinates");
    double value = 0.0;
    if (!parse_double(token, value)) fail_at(name, tokens.line(), "bad number " + io::quoted(token));
    if (!std::isfinite(value))
      fail_at(name, tokens.line(), "vertex coordinate " + io::quoted(token) + " is not finite");
    p[axis] = value;
  }
  // Optional w or per-vertex colour: must be numbers, not kept.
  for (std::string_view token = tokens.next_on_line('#'); !token.empty(); token = tokens.next_on_line('#')) {
    double ignored = 0.0;
    if (!parse_double(token, ignored)) fail_at(name, tokens.line(), "bad number " + io::quoted(token));
  }
  if (mesh.positions.size() >= std::numeric_limits<std::uint32_t>::max())
    fail_at(name, tokens.line(), "too many vertices");
  mesh.positions.push_back(p);
}

void read_face(Tokens& tokens, Mesh& mesh, std::vector<std::int64_t>& corners, const std::string& name) {
  const auto defined = static_cast<std::int64_t>(mesh.positions.size());
  corners.clear();
  for (std::string_view token = tokens.next_on_line('#'); !token.empty(); token = tokens.next_on_line('#')) {
    std::int64_t index = 0;
    if (!parse_corner(token, index)) fail_at(name, tokens.line(), "bad face corner " + io::quoted(token));
    if (index == 0) fail_at(name, tokens.line(), "face refers to vertex 0 (OBJ indices start at 1)");
    const std::int64_t resolved = index > 0 ? index - 1 : defined + index;
    if (resolved < 0 || resolved >= defined)
      fail_at(name, tokens.line(),
              "face refers to vertex " + std::to_string(index) + " but " + std::to_string(defined) +
                  " vertices are defined before it");
    corners.push_back(resolved);
    if (corners.size() > kMaxPolygon) break;
  }
  if (const std::string problem = add_polygon(mesh, corners, mesh.positions.size()); !problem.empty())
    fail_at(name, tokens.line(), "face " + problem);
}

}  // namespace

void encode_obj(const Mesh& mesh, ByteSink& out) {
  out += "# isopatch mesh: " + std::to_string(mesh.vertex_count()) + " vertices, " +
         std::to_string(mesh.triangle_count()) + " triangles\n";
  for (const Vec3& p : mesh.positions) {
    out += 'v';
    for (int axis = 0; axis < 3; ++axis) {
      out += ' ';
      append_number(out, p[axis]);
    }
    out += '\n';
  }
  for (const Triangle& t : mesh.triangles) {
    out += 'f';
    for (std::uint32_t v : t) {
      out += ' ';
      append_number(out, static_cast<std::int64_t>(v) + 1);
    }
    out += '\n';
  }
}

Mesh decode_obj(std::string_view bytes, const std::string& name) {
  Mesh mesh;
  std::vector<std::int64_t> corners;
  Tokens tokens(bytes);
  do {
    const std::string_view keyword = tokens.next_on_line('#');
    if (keyword.empty()) continue;
    if (keyword == "v") {
      read_vertex(tokens, mesh, name);
    } else if (keyword == "f") {
      read_face(tokens, mesh, corners, name);
    } else if (!is_statement(keyword)) {
      fail_at(name, tokens.line(), "not an OBJ statement: " + io::quoted(keyword));
    }
  } while (tokens.next_line());
  check_read_mesh(mesh, name);
  return mesh;
}

}  // namespace isopatch::io
