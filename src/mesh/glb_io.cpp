// glTF 2.0 binary (.glb) writer (mesh_io.hpp), streamed: the JSON chunk is made first from the counts
// (every length is known before any data), then the binary chunk is written straight from the mesh:
// positions, normals, COLOR_0 (when colours are given), one float accessor per vertex attribute, then
// the triangle indices. Only the unit normals are held apart from the mesh (12 bytes per vertex): each
// needs all triangles around its vertex before any normal is written. Follows the glTF 2.0
// specification (Khronos, 2021): GLB header, JSON and BIN chunks 4-byte aligned, application-specific
// attributes named with a leading underscore.
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/io_util.hpp"
#include "mesh/mesh_formats.hpp"

namespace isopatch::io {
namespace {

constexpr int kArrayBuffer = 34962;         // bufferView target of vertex attributes
constexpr int kElementArrayBuffer = 34963;  // bufferView target of indices
constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;

// "mean_curvature" -> "_MEAN_CURVATURE" (glTF: application-specific attributes start with '_').
std::string attribute_semantic(const std::string& name) {
  std::string semantic = "_";
  for (const char c : name)
    semantic.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  return semantic;
}

/// One accessor over its own buffer view: where it lies in the binary chunk and what it holds.
struct View {
  std::size_t offset = 0, bytes = 0, count = 0;
  int target = kArrayBuffer, component = kFloat;
  const char* type = "VEC3";
  std::string min, max;  // JSON arrays, for POSITION only
};

std::string number(double value) {
  std::string out;
  append_number(out, value);
  return out;
}

/// The JSON chunk: one scene, one node turning z up to glTF's y up, one mesh with one primitive. (Built
/// by appending pieces: GCC 12 warns wrongly about "literal" + std::string.)
std::string gltf_json(const std::vector<View>& views, const std::vector<std::string>& semantics,
                      std::size_t binary_bytes) {
  std::string json =
      R"({"asset":{"generator":"isopatch","version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)";
  const auto add = [&json](std::initializer_list<std::string_view> pieces) {
    for (const std::string_view piece : pieces) json += piece;
  };
  add({R"("nodes":[{"mesh":0,"rotation":[)", number(-std::sqrt(0.5)), ",0,0,", number(std::sqrt(0.5)),
       "]}],"});
  json += R"("meshes":[{"name":"isopatch","primitives":[{"attributes":{)";
  for (std::size_t a = 0; a < semantics.size(); ++a)
    add({a > 0 ? "," : "", "\"", semantics[a], "\":", std::to_string(a)});
  add({"},\"indices\":", std::to_string(views.size() - 1), R"(,"material":0,"mode":4}],)"});
  add({R"("extras":{"undefined_value":)", number(static_cast<double>(kGlbUndefined)), "}}],"});
  // Meshes clipped by their box are open: both sides shown.
  json += R"("materials":[{"name":"isopatch","doubleSided":true,"pbrMetallicRoughness":)"
          R"({"baseColorFactor":[1,1,1,1],"metallicFactor":0,"roughnessFactor":0.6}}],)";
  json += "\"accessors\":[";
  for (std::size_t k = 0; k < views.size(); ++k) {
    const View& v = views[k];
    add({k > 0 ? ",{" : "{", "\"bufferView\":", std::to_string(k), ",\"componentType\":",
         std::to_string(v.component), ",\"count\":", std::to_string(v.count), ",\"type\":\"", v.type, "\""});
    if (!v.min.empty()) add({",\"min\":", v.min, ",\"max\":", v.max});
    json += "}";
  }
  json += "],\"bufferViews\":[";
  for (std::size_t k = 0; k < views.size(); ++k)
    add({k > 0 ? ",{" : "{", "\"buffer\":0,\"byteOffset\":", std::to_string(views[k].offset),
         ",\"byteLength\":", std::to_string(views[k].bytes), ",\"target\":", std::to_string(views[k].target),
         "}"});
  add({"],\"buffers\":[{\"byteLength\":", std::to_string(binary_bytes), "}]}"});
  return json;
}

void put_floats(ByteSink& out, const Vec3& v) {
  for (int k = 0; k < 3; ++k) append_le(out, static_cast<float>(v[k]));
}

}  // namespace

void encode_glb(const Mesh& mesh, const std::vector<Vec3>& colours, ByteSink& out) {
  if (mesh.triangle_count() == 0) throw InputError("a glTF file needs at least one triangle");
  if (!colours.empty() && colours.size() != mesh.vertex_count())
    throw InputError("glTF: " + std::to_string(colours.size()) + " colours for " +
                     std::to_string(mesh.vertex_count()) + " vertices");
  std::vector<std::string> semantics{"POSITION", "NORMAL"};
  if (!colours.empty()) semantics.emplace_back("COLOR_0");
  std::map<std::string, std::string> named;  // semantic -> attribute, to catch "a" against "A"
  for (const VertexAttribute& attribute : mesh.attributes) {
    const std::string semantic = attribute_semantic(attribute.name);
    if (!named.emplace(semantic, attribute.name).second)
      throw InputError("glTF: attributes '" + named[semantic] + "' and '" + attribute.name +
                       "' would both be " + semantic);
    semantics.push_back(semantic);
  }
  const std::size_t n = mesh.vertex_count();
  std::vector<View> views;
  std::size_t offset = 0;
  const auto add = [&](std::size_t bytes, std::size_t count, const char* type, int target, int component) {
    View v;
    v.offset = offset;
    v.bytes = bytes;
    v.count = count;
    v.type = type;
    v.target = target;
    v.component = component;
    views.push_back(v);
    offset += bytes;  // every item is 4 bytes, so every view stays aligned
  };
  for (std::size_t k = 0; k < (colours.empty() ? 2U : 3U); ++k) add(12 * n, n, "VEC3", kArrayBuffer, kFloat);
  for (std::size_t a = 0; a < mesh.attributes.size(); ++a) add(4 * n, n, "SCALAR", kArrayBuffer, kFloat);
  add(12 * mesh.triangle_count(), 3 * mesh.triangle_count(), "SCALAR", kElementArrayBuffer, kUnsignedInt);
  // The bounds of the positions as written (floats).
  std::array<float, 3> lo{}, hi{};
  lo.fill(std::numeric_limits<float>::infinity());
  hi.fill(-std::numeric_limits<float>::infinity());
  for (const Vec3& p : mesh.positions)
    for (std::size_t k = 0; k < 3; ++k) {
      const auto f = static_cast<float>(p[static_cast<Eigen::Index>(k)]);
      lo[k] = std::min(lo[k], f);
      hi[k] = std::max(hi[k], f);
    }
  for (std::size_t k = 0; k < 3; ++k) {
    views[0].min += k == 0 ? "[" : ",";
    views[0].min += number(static_cast<double>(lo[k]));
    views[0].max += k == 0 ? "[" : ",";
    views[0].max += number(static_cast<double>(hi[k]));
  }
  views[0].min += "]";
  views[0].max += "]";

  std::string json = gltf_json(views, semantics, offset);
  json.resize((json.size() + 3) / 4 * 4, ' ');
  const std::size_t binary = offset;          // a multiple of 4
  append_le(out, std::uint32_t{0x46546C67});  // "glTF"
  append_le(out, std::uint32_t{2});
  append_le(out, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + binary));
  append_le(out, static_cast<std::uint32_t>(json.size()));
  append_le(out, std::uint32_t{0x4E4F534A});  // "JSON"
  out += json;
  append_le(out, static_cast<std::uint32_t>(binary));
  append_le(out, std::uint32_t{0x004E4942});  // "BIN\0"

  for (const Vec3& p : mesh.positions) put_floats(out, p);
  {
    // Area-weighted unit normals (as vertex_normals, mesh.hpp), summed as floats: 12 bytes per vertex.
    // glTF wants unit normals everywhere: a vertex without one (unused, or only in degenerate
    // triangles) gets +z.
    // Each term is divided by the squared diagonal of the bounds, so that floats hold it at any scale.
    double diagonal2 = 0.0;
    for (std::size_t k = 0; k < 3; ++k)
      diagonal2 += (static_cast<double>(hi[k]) - static_cast<double>(lo[k])) *
                   (static_cast<double>(hi[k]) - static_cast<double>(lo[k]));
    const double scale = diagonal2 > 0.0 && std::isfinite(diagonal2) ? 1.0 / diagonal2 : 1.0;
    std::vector<Eigen::Vector3f> normals(n, Eigen::Vector3f::Zero());
    for (const Triangle& t : mesh.triangles) {
      const Vec3& a = mesh.positions[t[0]];
      const Eigen::Vector3f normal =
          (scale * (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a)).cast<float>();
      for (const std::uint32_t v : t) normals[v] += normal;
    }
    for (const Eigen::Vector3f& sum : normals) {
      const float length = sum.norm();
      const Eigen::Vector3f unit =
          length > 0.0F && std::isfinite(length) ? Eigen::Vector3f(sum / length) : Eigen::Vector3f::UnitZ();
      for (int k = 0; k < 3; ++k) append_le(out, unit[k]);
    }
  }
  for (const Vec3& c : colours) {
    for (int k = 0; k < 3; ++k) {
      const auto f = static_cast<float>(c[k]);
      append_le(out, std::isfinite(f) ? std::clamp(f, 0.0F, 1.0F) : 0.0F);
    }
  }
  for (const VertexAttribute& attribute : mesh.attributes)
    for (const float value : attribute.values)
      append_le(out, std::isfinite(value) ? value : kGlbUndefined);  // glTF forbids NaN and infinity
  for (const Triangle& t : mesh.triangles)
    for (const std::uint32_t v : t) append_le(out, v);
}

}  // namespace isopatch::io
