/// \file ipatch_file.cpp
/// The .ipatch reader (ipatch_file.hpp): lines of whitespace-separated tokens, `#` comments.
#include "composite_model/ipatch_file.hpp"

#include "composite_model/control_polyhedron.hpp"
#include "composite_model/setback_solid.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <vector>

namespace isopatch {

namespace {

constexpr double kMaxCoordinate = 1e6;

struct Token {
  std::string_view text;
  std::size_t column = 0;  ///< 1-based
};

struct Line {
  std::size_t number = 0;  ///< 1-based
  std::vector<Token> tokens;
};

/// One parsed file: what either construction needs, and where each item came from.
struct Parsed {
  std::string source;
  PolygonMesh mesh;
  std::vector<std::size_t> vertex_lines, face_lines;
  std::vector<std::optional<Vec3>> normals;
  std::vector<ControlPolyhedron::EdgeShape> edge_shapes;
  std::vector<ControlPolyhedron::FaceShape> face_shapes;
  std::vector<SetbackSolid::EdgeRadius> edge_radii;
  std::vector<SetbackSolid::VertexSetback> vertex_setbacks;
  struct EdgeRef {
    std::uint32_t a, b;
    std::size_t line, column;
  };
  std::vector<EdgeRef> edge_refs;  ///< every edge option, to check that it names an edge
  std::optional<std::size_t> blend_line;
  double radius = 0.0, setback = 0.0;
  bool conic = true;
  std::string name;
  bool solid_box = false;
  std::size_t vertex_setback_line = 0;
};

class Reader {
 public:
  Reader(std::string_view source) : source_(source) {}

  [[noreturn]] void fail(std::size_t line, std::size_t column, const std::string& what) const {
    throw InputError(std::string(source_) + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                     what);
  }

  double number(const Line& l, std::size_t i) const {
    const Token& t = token(l, i, "a number");
    double v = 0.0;
    const char* end = t.text.data() + t.text.size();
    const auto [ptr, ec] = std::from_chars(t.text.data(), end, v);
    if (ec == std::errc::result_out_of_range)
      fail(l.number, t.column, "number out of range: " + std::string(t.text));
    if (ec != std::errc() || ptr != end)
      fail(l.number, t.column, "expected a number, found '" + std::string(t.text) + "'");
    if (!std::isfinite(v))
      fail(l.number, t.column, "numbers must be finite, found '" + std::string(t.text) + "'");
    if (std::abs(v) > kMaxCoordinate) fail(l.number, t.column, "numbers must not exceed 1e6 in size");
    return v;
  }

  Vec3 point(const Line& l, std::size_t i) const {
    return {number(l, i), number(l, i + 1), number(l, i + 2)};
  }

  /// A 1-based index in [1, limit], returned 0-based.
  std::uint32_t index(const Line& l, std::size_t i, std::size_t limit, const char* what) const {
    const Token& t = token(l, i, what);
    unsigned long long v = 0;
    const char* end = t.text.data() + t.text.size();
    const auto [ptr, ec] = std::from_chars(t.text.data(), end, v);
    if (ec != std::errc() || ptr != end || v == 0) {
      fail(l.number, t.column,
           std::string("expected ") + what + " (1-based), found '" + std::string(t.text) + "'");
    }
    if (v > limit) {
      fail(l.number, t.column,
           std::string(what) + " " + std::string(t.text) + " does not exist (there are " +
               std::to_string(limit) + ")");
    }
    return static_cast<std::uint32_t>(v - 1);
  }

  const Token& token(const Line& l, std::size_t i, const char* what) const {
    if (i >= l.tokens.size()) {
      const Token& last = l.tokens.back();
      fail(l.number, last.column + last.text.size(), std::string("missing ") + what);
    }
    return l.tokens[i];
  }

  void expect_count(const Line& l, std::size_t count) const {
    if (l.tokens.size() > count)
      fail(l.number, l.tokens[count].column, "unexpected '" + std::string(l.tokens[count].text) + "'");
    if (l.tokens.size() < count) token(l, count - 1, "fields");
  }

  void expect_word(const Line& l, std::size_t i, std::string_view word) const {
    const Token& t = token(l, i, std::string(word).c_str());
    if (t.text != word)
      fail(l.number, t.column, "expected '" + std::string(word) + "', found '" + std::string(t.text) + "'");
  }

 private:
  std::string_view source_;
};

std::vector<Line> split_lines(std::string_view text) {
  std::vector<Line> lines;
  std::size_t number = 0, pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view raw = text.substr(pos, end - pos);
    pos = end + 1;
    ++number;
    const std::size_t hash = raw.find('#');
    if (hash != std::string_view::npos) raw = raw.substr(0, hash);
    Line line{number, {}};
    std::size_t i = 0;
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
    while (i < raw.size()) {
      while (i < raw.size() && space(raw[i])) ++i;
      const std::size_t start = i;
      while (i < raw.size() && !space(raw[i])) ++i;
      if (i > start) line.tokens.push_back({raw.substr(start, i - start), start + 1});
    }
    if (!line.tokens.empty()) lines.push_back(std::move(line));
  }
  return lines;
}

void add_box(Parsed& p, const Reader& r, const Line& l) {
  r.expect_count(l, 8);
  const Vec3 lo = r.point(l, 2), hi = r.point(l, 5);
  if (!(lo.array() < hi.array()).all())
    r.fail(l.number, l.tokens[2].column, "the box must have lo < hi on every axis");
  for (int k = 0; k < 8; ++k) {
    p.mesh.vertices.push_back({k & 4 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 1 ? hi.z() : lo.z()});
    p.vertex_lines.push_back(l.number);
  }
  // Corner k has x from bit 2, y from bit 1, z from bit 0; faces counter-clockwise from outside.
  const std::vector<std::vector<std::uint32_t>> faces = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                                         {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for (const auto& f : faces) {
    p.mesh.faces.push_back(f);
    p.face_lines.push_back(l.number);
  }
  p.solid_box = true;
}

Parsed parse_lines(std::string_view text, const Reader& r, std::string source) {
  Parsed p;
  p.source = std::move(source);
  const std::vector<Line> lines = split_lines(text);
  if (lines.empty()) r.fail(1, 1, "empty file: expected the header 'ipatch-model 1'");
  const Line& header = lines.front();
  if (header.tokens[0].text != "ipatch-model")
    r.fail(header.number, header.tokens[0].column, "expected the header 'ipatch-model 1'");
  r.expect_count(header, 2);
  if (header.tokens[1].text != "1")
    r.fail(header.number, header.tokens[1].column,
           "unsupported ipatch-model version '" + std::string(header.tokens[1].text) +
               "' (this reader knows 1)");
  struct Deferred {
    const Line* line;
  };
  std::vector<Deferred> deferred;  // lines that name vertices or faces: read once all are known
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const Line& l = lines[k];
    const std::string_view key = l.tokens[0].text;
    if (key == "v") {
      r.expect_count(l, 4);
      if (p.mesh.vertices.size() >= kMaxIpatchVertices)
        r.fail(l.number, 1, "too many vertices (at most " + std::to_string(kMaxIpatchVertices) + ")");
      p.mesh.vertices.push_back(r.point(l, 1));
      p.vertex_lines.push_back(l.number);
    } else if (key == "f") {
      if (p.mesh.faces.size() >= kMaxIpatchFaces)
        r.fail(l.number, 1, "too many faces (at most " + std::to_string(kMaxIpatchFaces) + ")");
      if (l.tokens.size() < 4) r.token(l, 3, "vertex (a face needs at least 3)");
      if (l.tokens.size() > kMaxFaceSides + 1)
        r.fail(l.number, l.tokens[kMaxFaceSides + 1].column,
               "a face has at most " + std::to_string(kMaxFaceSides) + " vertices");
      p.mesh.faces.emplace_back();
      p.face_lines.push_back(l.number);
      deferred.push_back({&l});
    } else if (key == "vn" || key == "edge" || key == "face" || key == "vertex") {
      deferred.push_back({&l});  // read once every vertex and face is known
    } else if (key == "name") {
      if (l.tokens.size() < 2) r.token(l, 1, "name");
      p.name.clear();
      for (std::size_t t = 1; t < l.tokens.size(); ++t) {
        if (t > 1) p.name.push_back(' ');
        p.name.append(l.tokens[t].text);
      }
    } else if (key == "solid") {
      r.expect_word(l, 1, "box");
      if (p.solid_box || !p.mesh.vertices.empty())
        r.fail(l.number, 1, "'solid box' replaces the v and f lines: give one or the other");
      add_box(p, r, l);
    } else if (key == "blend") {
      if (p.blend_line) r.fail(l.number, 1, "a second 'blend' line");
      r.expect_word(l, 1, "radius");
      p.radius = r.number(l, 2);
      r.expect_word(l, 3, "setback");
      p.setback = r.number(l, 4);
      if (!(p.radius > 0.0)) r.fail(l.number, l.tokens[2].column, "the blend radius must be positive");
      if (!(p.setback > 0.0)) r.fail(l.number, l.tokens[4].column, "the setback must be positive");
      if (l.tokens.size() > 5) {
        r.expect_word(l, 5, "facecurve");
        const Token& mode = r.token(l, 6, "conic or planar");
        if (mode.text != "conic" && mode.text != "planar")
          r.fail(l.number, mode.column,
                 "facecurve is 'conic' or 'planar', found '" + std::string(mode.text) + "'");
        p.conic = mode.text == "conic";
        r.expect_count(l, 7);
      }
      p.blend_line = l.number;
    } else {
      r.fail(l.number, l.tokens[0].column,
             "unknown keyword '" + std::string(key) +
                 "' (expected v, f, vn, edge, face, name, solid, blend, vertex)");
    }
  }
  if (p.solid_box && !p.face_lines.empty() && p.mesh.faces.size() != 6) {
    r.fail(lines.back().number, 1, "'solid box' replaces the v and f lines: give one or the other");
  }
  const std::size_t nv = p.mesh.vertices.size(), nf = p.mesh.faces.size();
  p.normals.assign(nv, std::nullopt);
  std::size_t face = p.solid_box ? 6 : 0;
  for (const Deferred& d : deferred) {
    const Line& l = *d.line;
    const std::string_view key = l.tokens[0].text;
    if (key == "f") {
      if (p.solid_box) r.fail(l.number, 1, "'solid box' replaces the v and f lines: give one or the other");
      auto& f = p.mesh.faces[face++];
      for (std::size_t i = 1; i < l.tokens.size(); ++i) f.push_back(r.index(l, i, nv, "vertex"));
    } else if (key == "vn") {
      r.expect_count(l, 5);
      const std::uint32_t v = r.index(l, 1, nv, "vertex");
      const Vec3 n = r.point(l, 2);
      if (!(n.norm() > 0.0)) r.fail(l.number, l.tokens[2].column, "a vertex normal must not be zero");
      p.normals[v] = n;
    } else if (key == "edge") {
      const std::uint32_t a = r.index(l, 1, nv, "vertex"), b = r.index(l, 2, nv, "vertex");
      if (a == b) r.fail(l.number, l.tokens[2].column, "an edge joins two different vertices");
      const Token& what = r.token(l, 3, "weight, through or radius");
      p.edge_refs.push_back({a, b, l.number, l.tokens[1].column});
      if (what.text == "weight") {
        r.expect_count(l, 5);
        const double w = r.number(l, 4);
        if (!(w > 0.0)) r.fail(l.number, l.tokens[4].column, "a curve weight must be positive");
        p.edge_shapes.push_back({a, b, w, std::nullopt});
      } else if (what.text == "through") {
        r.expect_count(l, 7);
        p.edge_shapes.push_back({a, b, std::nullopt, r.point(l, 4)});
      } else if (what.text == "radius") {
        r.expect_count(l, 5);
        const double radius = r.number(l, 4);
        if (!(radius > 0.0)) r.fail(l.number, l.tokens[4].column, "a blend radius must be positive");
        p.edge_radii.push_back({a, b, radius});
      } else {
        r.fail(l.number, what.column,
               "expected weight, through or radius, found '" + std::string(what.text) + "'");
      }
    } else if (key == "face") {
      ControlPolyhedron::FaceShape s;
      s.face = r.index(l, 1, nf, "face");
      r.expect_word(l, 2, "centre");
      s.centre = r.point(l, 3);
      if (l.tokens.size() > 6) {
        r.expect_word(l, 6, "d");
        for (std::size_t i = 7; i < l.tokens.size(); ++i) {
          const double v = r.number(l, i);
          if (!(v > 0.0)) r.fail(l.number, l.tokens[i].column, "weight factors must be positive");
          s.d.push_back(v);
        }
        if (s.d.size() != p.mesh.faces[s.face].size()) {
          r.fail(l.number, l.tokens[6].column,
                 "face " + std::string(l.tokens[1].text) + " has " +
                     std::to_string(p.mesh.faces[s.face].size()) + " sides: give as many factors after d");
        }
      }
      p.face_shapes.push_back(std::move(s));
    } else if (key == "vertex") {
      r.expect_count(l, 4);
      const std::uint32_t v = r.index(l, 1, nv, "vertex");
      r.expect_word(l, 2, "setback");
      const double s = r.number(l, 3);
      if (!(s > 0.0)) r.fail(l.number, l.tokens[3].column, "a setback must be positive");
      p.vertex_setbacks.push_back({v, s});
      if (p.vertex_setback_line == 0) p.vertex_setback_line = l.number;
    }
  }
  if (nv == 0) r.fail(lines.back().number, 1, "no vertices ('v x y z' lines or 'solid box')");
  return p;
}

/// Options of one construction are refused in the other.
void check_options(const Parsed& p, const Reader& r) {
  if (p.blend_line) {
    const bool normals =
        std::any_of(p.normals.begin(), p.normals.end(), [](const auto& n) { return n.has_value(); });
    if (!p.edge_shapes.empty() || !p.face_shapes.empty() || normals) {
      r.fail(*p.blend_line, 1, "a blended solid takes no vn, 'edge ... weight/through' or 'face' lines");
    }
  } else if (!p.edge_radii.empty() || !p.vertex_setbacks.empty()) {
    const std::size_t line = p.edge_refs.empty() ? p.vertex_setback_line : p.edge_refs.front().line;
    r.fail(line, 1, "'edge ... radius' and 'vertex ... setback' need a 'blend' line");
  }
}

}  // namespace

Composite parse_ipatch(std::string_view text, std::string_view source_name) {
  const std::string source(source_name);
  const Reader r(source);
  if (text.size() > kMaxIpatchBytes) {
    throw InputError(source + ": larger than " + std::to_string(kMaxIpatchBytes) + " bytes");
  }
  Parsed p = parse_lines(text, r, source);
  check_options(p, r);
  if (auto problem = find_topology_problem(p.mesh)) {
    if (problem->face) r.fail(p.face_lines[*problem->face], 1, problem->message);
    if (problem->vertex) r.fail(p.vertex_lines[*problem->vertex], 1, problem->message);
    throw InputError(source + ": " + problem->message);
  }
  const auto edges = half_edges(p.mesh);
  for (const auto& e : p.edge_refs) {
    if (!edges.count({e.a, e.b}) && !edges.count({e.b, e.a})) {
      r.fail(e.line, e.column,
             "vertices " + std::to_string(e.a + 1) + " and " + std::to_string(e.b + 1) +
                 " are not joined by an edge");
    }
  }
  try {
    if (p.blend_line) {
      SetbackSolid s;
      s.name = p.name.empty() ? source : p.name;
      s.mesh = std::move(p.mesh);
      s.radius = p.radius;
      s.setback = p.setback;
      s.conic_face_curves = p.conic;
      s.edge_radii = std::move(p.edge_radii);
      s.vertex_setbacks = std::move(p.vertex_setbacks);
      return build_setback_solid(s);
    }
    ControlPolyhedron c;
    c.name = p.name.empty() ? source : p.name;
    c.mesh = std::move(p.mesh);
    c.normals = std::move(p.normals);
    c.edges = std::move(p.edge_shapes);
    c.faces = std::move(p.face_shapes);
    return build_control_polyhedron(c);
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  }
}

Composite read_ipatch(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot open for reading");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw IoError(path + ": cannot read");
  if (static_cast<std::size_t>(size) > kMaxIpatchBytes) {
    throw IoError(path + ": larger than " + std::to_string(kMaxIpatchBytes) + " bytes, not an .ipatch model");
  }
  in.seekg(0, std::ios::beg);
  std::string text(static_cast<std::size_t>(size), '\0');
  if (size > 0 && !in.read(text.data(), size)) throw IoError(path + ": cannot read");
  return parse_ipatch(text, path);
}

}  // namespace isopatch
