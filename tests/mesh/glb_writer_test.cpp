// The .glb writer read back by TinyGLTF's loader: the layout mesh_io.hpp promises (positions with
// bounds, unit normals, indices, COLOR_0, one `_NAME` accessor per attribute, the undefined value).
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>

#include <tiny_gltf.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "mesh_fixtures.hpp"

namespace isopatch {
namespace {

tinygltf::Model load(const std::string& bytes) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  const bool ok = loader.LoadBinaryFromMemory(&model, &error, &warning,
                                              reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<unsigned int>(bytes.size()));
  EXPECT_TRUE(ok) << error;
  EXPECT_EQ(warning, "");
  return model;
}

template <typename T>
std::vector<T> read(const tinygltf::Model& model, int accessor_index) {
  const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(accessor_index));
  const tinygltf::BufferView& v = model.bufferViews.at(static_cast<std::size_t>(a.bufferView));
  const std::size_t components = a.type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
  std::vector<T> out(a.count * components);
  std::memcpy(out.data(), model.buffers.at(0).data.data() + v.byteOffset + a.byteOffset,
              out.size() * sizeof(T));
  return out;
}

TEST(GlbWriter, HoldsPositionsNormalsIndicesColoursAndAttributes) {
  Mesh mesh = test::icosahedron();
  std::vector<float> with_nan = mesh.attributes[0].values;
  with_nan[3] = std::numeric_limits<float>::quiet_NaN();
  with_nan[4] = std::numeric_limits<float>::infinity();
  mesh.set_attribute("mean_curvature", with_nan);
  std::vector<Vec3> colours;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    colours.emplace_back(0.05 * static_cast<double>(v), 0.5, 2.0);

  const tinygltf::Model model = load(encode_mesh(mesh, MeshFormat::Glb, colours));
  ASSERT_EQ(model.meshes.size(), 1u);
  const tinygltf::Primitive& p = model.meshes[0].primitives.at(0);
  EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);

  const std::vector<float> xyz = read<float>(model, p.attributes.at("POSITION"));
  ASSERT_EQ(xyz.size(), 3 * mesh.vertex_count());
  const Box box = bounding_box(mesh);
  const tinygltf::Accessor& position = model.accessors[static_cast<std::size_t>(p.attributes.at("POSITION"))];
  for (int k = 0; k < 3; ++k) {
    EXPECT_FLOAT_EQ(static_cast<float>(position.minValues.at(static_cast<std::size_t>(k))),
                    static_cast<float>(box.lo[k]));
    EXPECT_FLOAT_EQ(static_cast<float>(position.maxValues.at(static_cast<std::size_t>(k))),
                    static_cast<float>(box.hi[k]));
  }
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(xyz[3 * v + static_cast<std::size_t>(k)], static_cast<float>(mesh.positions[v][k]));

  const std::vector<float> normals = read<float>(model, p.attributes.at("NORMAL"));
  const std::vector<Vec3> expected = vertex_normals(mesh);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3 n(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
    EXPECT_NEAR(n.norm(), 1.0, 1e-6);
    EXPECT_GT(n.dot(expected[v]), 0.999999);
    EXPECT_GT(n.dot(mesh.positions[v] - Vec3::Constant(0.1)), 0.0) << "outward";
  }

  const std::vector<std::uint32_t> indices = read<std::uint32_t>(model, p.indices);
  ASSERT_EQ(indices.size(), 3 * mesh.triangle_count());
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(indices[3 * t + k], mesh.triangles[t][k]);

  const std::vector<float> rgb = read<float>(model, p.attributes.at("COLOR_0"));
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    EXPECT_FLOAT_EQ(rgb[3 * v], static_cast<float>(colours[v].x()));
    EXPECT_FLOAT_EQ(rgb[3 * v + 1], 0.5f);
    EXPECT_FLOAT_EQ(rgb[3 * v + 2], 1.0f) << "clamped to [0, 1]";
  }

  for (const VertexAttribute& a : mesh.attributes) {
    std::string semantic = "_";
    for (char c : a.name) semantic.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    ASSERT_TRUE(p.attributes.count(semantic)) << semantic;
    const std::vector<float> values = read<float>(model, p.attributes.at(semantic));
    ASSERT_EQ(values.size(), mesh.vertex_count());
    for (std::size_t v = 0; v < values.size(); ++v) {
      if (std::isfinite(a.values[v]))
        EXPECT_EQ(std::memcmp(&values[v], &a.values[v], sizeof(float)), 0) << semantic << " " << v;
      else
        EXPECT_EQ(values[v], kGlbUndefined) << semantic << " " << v;
    }
  }
  EXPECT_EQ(model.meshes[0].extras.Get("undefined_value").GetNumberAsDouble(),
            static_cast<double>(kGlbUndefined));
  ASSERT_EQ(model.nodes.size(), 1u);
  EXPECT_EQ(model.nodes[0].rotation.size(), 4u) << "z up turned to y up";
  EXPECT_TRUE(model.materials.at(0).doubleSided);
}

TEST(GlbWriter, WithoutColoursHasNoColour0) {
  const tinygltf::Model model = load(encode_mesh(test::octahedron(), MeshFormat::Glb));
  EXPECT_FALSE(model.meshes.at(0).primitives.at(0).attributes.count("COLOR_0"));
  EXPECT_EQ(format_from_path("a/B.GLB"), MeshFormat::Glb);
}

TEST(GlbWriter, RefusesWhatGltfCannotHold) {
  EXPECT_THROW(encode_mesh(Mesh{}, MeshFormat::Glb), InputError);
  EXPECT_THROW(encode_mesh(test::octahedron(), MeshFormat::Glb, {Vec3(1, 0, 0)}), InputError);
  Mesh clash = test::octahedron();
  clash.set_attribute("a", std::vector<float>(6, 1.0f));
  clash.set_attribute("A", std::vector<float>(6, 2.0f));
  EXPECT_THROW(encode_mesh(clash, MeshFormat::Glb), InputError);
  EXPECT_THROW(decode_mesh("glTF", MeshFormat::Glb), IoError);
}

}  // namespace
}  // namespace isopatch
