// glTF 2.0 binary (.glb) writer (mesh_io.hpp): the container and its JSON by TinyGLTF (Debian's
// libtinygltf), the data laid out here in one buffer: positions, normals, COLOR_0 (when colours are
// given), one float accessor per vertex attribute, then the triangle indices.
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>

#include "mesh/mesh_formats.hpp"

namespace isopatch::io {
namespace {

constexpr int kArrayBuffer = 34962;         // bufferView target of vertex attributes
constexpr int kElementArrayBuffer = 34963;  // bufferView target of indices

// Appends floats (or indices) to the buffer as a new buffer view and returns its accessor.
class BufferBuilder {
 public:
  explicit BufferBuilder(tinygltf::Model& model) : model_(model) { model_.buffers.emplace_back(); }

  int add(const void* data, std::size_t bytes, int target, int component, int type, std::size_t count) {
    std::vector<unsigned char>& buffer = model_.buffers.front().data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();  // every item is 4 bytes, so every view stays aligned
    view.byteLength = bytes;
    view.target = target;
    const auto* first = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), first, first + bytes);
    model_.bufferViews.push_back(view);
    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model_.bufferViews.size() - 1);
    accessor.byteOffset = 0;
    accessor.componentType = component;
    accessor.type = type;
    accessor.count = count;
    model_.accessors.push_back(accessor);
    return static_cast<int>(model_.accessors.size() - 1);
  }

  int add_vec3(const std::vector<float>& xyz) {
    return add(xyz.data(), xyz.size() * sizeof(float), kArrayBuffer, TINYGLTF_COMPONENT_TYPE_FLOAT,
               TINYGLTF_TYPE_VEC3, xyz.size() / 3);
  }

 private:
  tinygltf::Model& model_;
};

std::vector<float> flatten(const std::vector<Vec3>& points) {
  std::vector<float> xyz;
  xyz.reserve(3 * points.size());
  for (const Vec3& p : points)
    for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(p[k]));
  return xyz;
}

// "mean_curvature" -> "_MEAN_CURVATURE" (glTF: application-specific attributes start with '_').
std::string attribute_semantic(const std::string& name) {
  std::string semantic = "_";
  for (const char c : name)
    semantic.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  return semantic;
}

tinygltf::Material field_material() {
  tinygltf::Material material;
  material.name = "isopatch";
  material.doubleSided = true;  // meshes clipped by their box are open: show the inside too
  material.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.6;
  return material;
}

}  // namespace

std::string encode_glb(const Mesh& mesh, const std::vector<Vec3>& colours) {
  if (mesh.triangle_count() == 0) throw InputError("a glTF file needs at least one triangle");
  if (!colours.empty() && colours.size() != mesh.vertex_count())
    throw InputError("glTF: " + std::to_string(colours.size()) + " colours for " +
                     std::to_string(mesh.vertex_count()) + " vertices");
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "isopatch";
  BufferBuilder buffer(model);
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = 0;

  const std::vector<float> positions = flatten(mesh.positions);
  const int position = buffer.add_vec3(positions);
  std::vector<double> lo(3, std::numeric_limits<double>::infinity());
  std::vector<double> hi(3, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], static_cast<double>(positions[i]));
    hi[i % 3] = std::max(hi[i % 3], static_cast<double>(positions[i]));
  }
  model.accessors[static_cast<std::size_t>(position)].minValues = lo;
  model.accessors[static_cast<std::size_t>(position)].maxValues = hi;
  primitive.attributes["POSITION"] = position;

  // glTF wants unit normals everywhere: a vertex without one (unused, or only in degenerate
  // triangles) gets +z.
  std::vector<Vec3> normals = vertex_normals(mesh);
  for (Vec3& n : normals)
    if (n.squaredNorm() == 0.0) n = Vec3::UnitZ();
  primitive.attributes["NORMAL"] = buffer.add_vec3(flatten(normals));

  if (!colours.empty()) {
    std::vector<float> rgb = flatten(colours);
    for (float& c : rgb) c = std::isfinite(c) ? std::clamp(c, 0.0f, 1.0f) : 0.0f;
    primitive.attributes["COLOR_0"] = buffer.add_vec3(rgb);
  }

  std::map<std::string, std::string> semantics;  // semantic -> attribute, to catch "a" against "A"
  for (const VertexAttribute& attribute : mesh.attributes) {
    const std::string semantic = attribute_semantic(attribute.name);
    if (!semantics.emplace(semantic, attribute.name).second)
      throw InputError("glTF: attributes '" + semantics[semantic] + "' and '" + attribute.name +
                       "' would both be " + semantic);
    std::vector<float> values = attribute.values;
    for (float& v : values)
      if (!std::isfinite(v)) v = kGlbUndefined;  // glTF forbids NaN and infinity in accessors
    primitive.attributes[semantic] =
        buffer.add(values.data(), values.size() * sizeof(float), kArrayBuffer, TINYGLTF_COMPONENT_TYPE_FLOAT,
                   TINYGLTF_TYPE_SCALAR, values.size());
  }

  std::vector<std::uint32_t> indices;
  indices.reserve(3 * mesh.triangle_count());
  for (const Triangle& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
  primitive.indices = buffer.add(indices.data(), indices.size() * sizeof(std::uint32_t), kElementArrayBuffer,
                                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());

  tinygltf::Mesh gltf_mesh;
  gltf_mesh.name = "isopatch";
  gltf_mesh.primitives.push_back(primitive);
  tinygltf::Value::Object extras;
  extras["undefined_value"] = tinygltf::Value(static_cast<double>(kGlbUndefined));
  gltf_mesh.extras = tinygltf::Value(extras);
  model.meshes.push_back(gltf_mesh);
  model.materials.push_back(field_material());

  // isopatch has z up, glTF y up: the node turns the mesh by -90 degrees about x.
  tinygltf::Node node;
  node.mesh = 0;
  node.rotation = {-std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)};
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true))
    throw IoError("glTF: TinyGLTF could not write the model");
  return out.str();
}

}  // namespace isopatch::io
