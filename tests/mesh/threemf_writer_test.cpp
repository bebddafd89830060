// The .3mf writer read back by lib3mf's own reader: one mesh object with the mesh's positions (to the
// six decimals lib3mf prints) and triangles, millimetres; the same bytes every time; what 3MF cannot
// hold refused.
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>

#include <Model/COM/NMR_DLLInterfaces.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mesh_fixtures.hpp"

namespace isopatch {
namespace {

/// What lib3mf reads from a package: the unit, and the vertices and triangles of each mesh object.
struct ReadBack {
  DWORD unit = 0;
  std::vector<std::vector<NMR::MODELMESHVERTEX>> vertices;
  std::vector<std::vector<NMR::MODELMESHTRIANGLE>> triangles;
};

ReadBack read_back(std::string bytes) {
  ReadBack out;
  NMR::PLib3MFModel* model = nullptr;
  EXPECT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
  NMR::PLib3MFModelReader* reader = nullptr;
  EXPECT_EQ(NMR::lib3mf_model_queryreader(model, "3mf", &reader), LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_reader_readfrombuffer(reader, reinterpret_cast<BYTE*>(bytes.data()), bytes.size()),
            LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_model_getunit(model, &out.unit), LIB3MF_OK);
  NMR::PLib3MFModelResourceIterator* objects = nullptr;
  EXPECT_EQ(NMR::lib3mf_model_getmeshobjects(model, &objects), LIB3MF_OK);
  BOOL more = 0;
  while (NMR::lib3mf_resourceiterator_movenext(objects, &more) == LIB3MF_OK && more) {
    NMR::PLib3MFModelResource* object = nullptr;
    EXPECT_EQ(NMR::lib3mf_resourceiterator_getcurrent(objects, &object), LIB3MF_OK);
    DWORD nv = 0, nt = 0;
    NMR::lib3mf_meshobject_getvertexcount(object, &nv);
    NMR::lib3mf_meshobject_gettrianglecount(object, &nt);
    out.vertices.emplace_back(nv);
    out.triangles.emplace_back(nt);
    NMR::lib3mf_meshobject_getvertices(object, out.vertices.back().data(), nv, nullptr);
    NMR::lib3mf_meshobject_gettriangleindices(object, out.triangles.back().data(), nt, nullptr);
    NMR::lib3mf_release(object);
  }
  NMR::lib3mf_release(objects);
  NMR::lib3mf_release(reader);
  NMR::lib3mf_release(model);
  return out;
}

TEST(ThreeMfWriter, HoldsOneMeshObjectWithThePositionsAndTrianglesInMillimetres) {
  const Mesh mesh = test::icosahedron();
  const std::string bytes = encode_mesh(mesh, MeshFormat::ThreeMf);
  ASSERT_GT(bytes.size(), 4u);
  EXPECT_EQ(bytes.substr(0, 2), "PK");  // an OPC package is a zip archive
  const ReadBack r = read_back(bytes);
  EXPECT_EQ(r.unit, static_cast<DWORD>(NMR::MODELUNIT_MILLIMETER));
  ASSERT_EQ(r.vertices.size(), 1u);
  ASSERT_EQ(r.vertices[0].size(), mesh.positions.size());
  ASSERT_EQ(r.triangles[0].size(), mesh.triangles.size());
  // lib3mf prints six decimals (a nanometre in millimetres): positions come back to within 1e-6.
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(r.vertices[0][v].m_fPosition[a], mesh.positions[v][a], 1.01e-6);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(r.triangles[0][t].m_nIndices[k], mesh.triangles[t][k]);
}

TEST(ThreeMfWriter, WritesTheSameBytesEveryTime) {
  const Mesh mesh = test::octahedron();
  EXPECT_EQ(encode_mesh(mesh, MeshFormat::ThreeMf), encode_mesh(mesh, MeshFormat::ThreeMf));
  EXPECT_EQ(format_from_path("out/Part.3MF"), MeshFormat::ThreeMf);
}

TEST(ThreeMfWriter, RefusesAMeshWithoutTrianglesAndIsNotRead) {
  EXPECT_THROW(encode_mesh(Mesh{}, MeshFormat::ThreeMf), InputError);
  const std::string bytes = encode_mesh(test::octahedron(), MeshFormat::ThreeMf);
  EXPECT_THROW(decode_mesh(bytes, MeshFormat::ThreeMf), IoError);
}

}  // namespace
}  // namespace isopatch
