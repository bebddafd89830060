// Mesh I/O on valid files: every format round-trips exactly (doubles bit for bit, STL in float), and
// the readers accept the variants other programs write (OBJ corner forms and relative indices, PLY
// element order and types, big-endian PLY, OFF comments and colours, ASCII STL).
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>

#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <fstream>

namespace isopatch {
namespace {

using test::same_bits;

void expect_same_geometry(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count());
  ASSERT_EQ(a.triangles, b.triangles);
  for (std::size_t v = 0; v < a.vertex_count(); ++v)
    for (int axis = 0; axis < 3; ++axis)
      ASSERT_TRUE(same_bits(a.positions[v][axis], b.positions[v][axis]))
          << "vertex " << v << " axis " << axis << ": " << a.positions[v][axis] << " vs "
          << b.positions[v][axis];
}

void expect_same_attributes(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.attributes.size(), b.attributes.size());
  for (std::size_t k = 0; k < a.attributes.size(); ++k) {
    EXPECT_EQ(a.attributes[k].name, b.attributes[k].name);
    ASSERT_EQ(a.attributes[k].values.size(), b.attributes[k].values.size());
    for (std::size_t v = 0; v < a.attributes[k].values.size(); ++v)
      EXPECT_TRUE(same_bits(a.attributes[k].values[v], b.attributes[k].values[v]))
          << a.attributes[k].name << "[" << v << "]";
  }
}

Mesh write_then_read(const Mesh& mesh, const test::TempDir& dir, const std::string& file, MeshFormat format) {
  const std::string path = dir.file(file);
  write_mesh(mesh, path, format);
  return read_mesh(path, format);
}

Mesh decode(const std::string& text, MeshFormat format) {
  return decode_mesh(text, format, "test");
}

TEST(MeshIo, FormatFromExtension) {
  EXPECT_EQ(format_from_path("a/b.obj"), MeshFormat::Obj);
  EXPECT_EQ(format_from_path("B.OBJ"), MeshFormat::Obj);
  EXPECT_EQ(format_from_path("x.Ply"), MeshFormat::PlyBinary);
  EXPECT_EQ(format_from_path("x.off"), MeshFormat::Off);
  EXPECT_EQ(format_from_path("x.stl"), MeshFormat::Stl);
  for (const char* bad : {"x", "x.obj.gz", "x.vtk", ".obj/", "obj"})
    EXPECT_THROW(format_from_path(bad), IoError) << bad;
}

TEST(MeshIo, DoubleFormatsRoundTripBitForBit) {
  const test::TempDir dir;
  Mesh mesh = test::icosahedron();
  // Values whose shortest decimal form is long or unusual.
  mesh.positions[0] = Vec3(-0.0, 4.9406564584124654e-324, 1.7976931348623157e308);
  mesh.positions[1] = Vec3(1.0 / 3.0, -2.2250738585072014e-308, 123456789012345678.0);
  for (const auto& [file, format] :
       {std::pair{"m.obj", MeshFormat::Obj}, std::pair{"m.off", MeshFormat::Off},
        std::pair{"a.ply", MeshFormat::PlyAscii}, std::pair{"b.ply", MeshFormat::PlyBinary}}) {
    SCOPED_TRACE(file);
    const Mesh back = write_then_read(mesh, dir, file, format);
    expect_same_geometry(mesh, back);
    if (format == MeshFormat::PlyAscii || format == MeshFormat::PlyBinary) {
      expect_same_attributes(mesh, back);
    } else {
      EXPECT_TRUE(back.attributes.empty());
    }
  }
}

TEST(MeshIo, PlyKeepsNonFiniteAttributeValues) {
  Mesh mesh = test::octahedron();
  mesh.set_attribute("h",
                     {1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                      -std::numeric_limits<float>::infinity(), 0.0f, -1.5f});
  for (MeshFormat format : {MeshFormat::PlyAscii, MeshFormat::PlyBinary}) {
    const Mesh back = decode(encode_mesh(mesh, format), format);
    const std::vector<float>* h = back.find_attribute("h");
    ASSERT_NE(h, nullptr);
    EXPECT_TRUE(std::isnan((*h)[1]));
    EXPECT_EQ((*h)[2], std::numeric_limits<float>::infinity());
    EXPECT_EQ((*h)[3], -std::numeric_limits<float>::infinity());
    EXPECT_EQ((*h)[5], -1.5f);
  }
}

TEST(MeshIo, StlRoundTripMergesCornersBackIntoAClosedMesh) {
  const test::TempDir dir;
  for (const Mesh& mesh : {test::octahedron(), test::icosahedron()}) {
    const Mesh back = write_then_read(mesh, dir, "m.stl", MeshFormat::Stl);
    ASSERT_EQ(back.vertex_count(), mesh.vertex_count());
    ASSERT_EQ(back.triangle_count(), mesh.triangle_count());
    EXPECT_TRUE(back.attributes.empty());
    EXPECT_TRUE(test::closed_and_oriented(back));
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
      for (int c = 0; c < 3; ++c)
        for (int axis = 0; axis < 3; ++axis)
          ASSERT_EQ(back.positions[back.triangles[t][c]][axis],
                    static_cast<double>(static_cast<float>(mesh.positions[mesh.triangles[t][c]][axis])));
  }
}

TEST(MeshIo, EmptyMeshRoundTripsInEveryFormat) {
  for (MeshFormat format :
       {MeshFormat::Obj, MeshFormat::PlyAscii, MeshFormat::PlyBinary, MeshFormat::Off, MeshFormat::Stl}) {
    const Mesh back = decode(encode_mesh(Mesh{}, format), format);
    EXPECT_EQ(back.vertex_count(), 0u);
    EXPECT_EQ(back.triangle_count(), 0u);
  }
}

TEST(MeshIo, ObjReadsCornerFormsRelativeIndicesAndPolygons) {
  const std::string text =
      "# a unit square and a triangle\nmtllib x.mtl\no square\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0 1.0\nv 0 1 0 0.5 0.5 0.5\n"
      "vt 0 0\nvn 0 0 1\ng top\ns off\nusemtl red\n"
      "f 1/1/1 2/1/1 3//1 4/1   # a quad\n"
      "v +2 -0 3e-1\n"
      "f -3 -2 -1\n"
      "l 1 2\n";
  const Mesh m = decode(text, MeshFormat::Obj);
  ASSERT_EQ(m.vertex_count(), 5u);
  ASSERT_EQ(m.triangle_count(), 3u);
  EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (Triangle{0, 2, 3}));
  EXPECT_EQ(m.triangles[2], (Triangle{2, 3, 4}));
  EXPECT_EQ(m.positions[4], Vec3(2, 0, 0.3));
}

TEST(MeshIo, OffReadsCommentsPolygonsAndColours) {
  const std::string text =
      "OFF # cube corner\n\n# counts\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0 # comment\n0.5 0.5 1\n"
      "4 0 1 2 3 255 0 0\n3 0 1 4\n";
  const Mesh m = decode(text, MeshFormat::Off);
  ASSERT_EQ(m.vertex_count(), 5u);
  ASSERT_EQ(m.triangle_count(), 3u);
  EXPECT_EQ(m.triangles[1], (Triangle{0, 2, 3}));
  EXPECT_EQ(m.triangles[2], (Triangle{0, 1, 4}));
}

TEST(MeshIo, PlyReadsAnyElementOrderTypesAndSkipsUnknownElements) {
  const std::string text =
      "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\n"
      "element material 2\r\nproperty list uint8 int tags\r\nproperty float shine\r\n"
      "element face 2\r\nproperty uchar flags\r\nproperty list ushort uint vertex_index\r\n"
      "element vertex 4\r\nproperty int8 x\r\nproperty short y\r\nproperty uint z\r\n"
      "property uchar red\r\nproperty list uchar float normals\r\nproperty float64 quality\r\n"
      "end_header\r\n"
      "3 1 2 3 0.5\r\n0 0\r\n"
      "7 4 0 1 2 3\r\n0 3 3 2 1\r\n"
      "-1 -2 3 255 0 0.25\r\n1 0 0 0 1 9 0.5\r\n1 1 0 10 2 1 1 1\r\n0 1 7 20 0 -1e-3\r\n";
  const Mesh m = decode(text, MeshFormat::PlyAscii);
  ASSERT_EQ(m.vertex_count(), 4u);
  ASSERT_EQ(m.triangle_count(), 3u);
  EXPECT_EQ(m.positions[0], Vec3(-1, -2, 3));
  EXPECT_EQ(m.positions[3], Vec3(0, 1, 7));
  EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (Triangle{0, 2, 3}));
  EXPECT_EQ(m.triangles[2], (Triangle{3, 2, 1}));
  ASSERT_EQ(m.attributes.size(), 2u);
  EXPECT_EQ(m.attributes[0].name, "red");
  EXPECT_EQ(m.attributes[0].values, (std::vector<float>{255, 0, 10, 20}));
  EXPECT_EQ(m.attributes[1].name, "quality");
  EXPECT_EQ(m.attributes[1].values[3], -1e-3f);
}

// The binary little-endian encoding of a mesh, rewritten big-endian by hand: both must read the same.
TEST(MeshIo, PlyReadsBigEndian) {
  const Mesh mesh = test::icosahedron();
  const std::string little = encode_mesh(mesh, MeshFormat::PlyBinary);
  const std::size_t body = little.find("end_header\n") + 11;
  std::string big = little.substr(0, body);
  big.replace(big.find("binary_little_endian"), 20, "binary_big_endian");
  std::size_t p = body;
  auto swap_copy = [&](std::size_t size) {
    for (std::size_t i = 0; i < size; ++i) big += little[p + size - 1 - i];
    p += size;
  };
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    for (int axis = 0; axis < 3; ++axis) swap_copy(8);
    for (std::size_t k = 0; k < mesh.attributes.size(); ++k) swap_copy(4);
  }
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    swap_copy(1);
    for (int c = 0; c < 3; ++c) swap_copy(4);
  }
  ASSERT_EQ(p, little.size());
  const Mesh back = decode(big, MeshFormat::PlyBinary);
  expect_same_geometry(mesh, back);
  expect_same_attributes(mesh, back);
}

TEST(MeshIo, PlyFileWithEitherEncodingIsReadByExtension) {
  const test::TempDir dir;
  const Mesh mesh = test::icosahedron();
  write_mesh(mesh, dir.file("ascii.ply"), MeshFormat::PlyAscii);
  write_mesh(mesh, dir.file("binary.PLY"));
  expect_same_geometry(mesh, read_mesh(dir.file("ascii.ply")));
  expect_same_geometry(mesh, read_mesh(dir.file("binary.PLY")));
  expect_same_geometry(mesh, read_mesh(dir.file("binary.PLY"), MeshFormat::PlyAscii));
}

TEST(MeshIo, ReadsAsciiStl) {
  const std::string text =
      "solid tetra made by hand\n"
      " facet normal 0 0 -1\n  outer loop\n   vertex 0 0 0\n   vertex 0 1 0\n   vertex 1 0 0\n  endloop\n "
      "endfacet\n"
      " facet normal 0 -1 0\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 0 1\n  endloop\n "
      "endfacet\n"
      " facet normal -1 0 0\n  outer loop\n   vertex 0 0 0\n   vertex 0 0 1\n   vertex 0 1 0\n  endloop\n "
      "endfacet\n"
      " facet normal 1 1 1\n  outer loop\n   vertex 1 0 0\n   vertex 0 1 0\n   vertex 0 0 1\n  endloop\n "
      "endfacet\n"
      "endsolid tetra\n";
  const Mesh m = decode(text, MeshFormat::Stl);
  EXPECT_EQ(m.vertex_count(), 4u);
  EXPECT_EQ(m.triangle_count(), 4u);
  EXPECT_TRUE(test::closed_and_oriented(m));
}

TEST(MeshIo, BinaryStlWhoseHeaderSaysSolidIsStillBinary) {
  std::string bytes = encode_mesh(test::octahedron(), MeshFormat::Stl);
  bytes.replace(0, 5, "solid");
  const Mesh m = decode(bytes, MeshFormat::Stl);
  EXPECT_EQ(m.triangle_count(), 8u);
}

TEST(MeshIo, WriteChecksTheMeshAndThePath) {
  const test::TempDir dir;
  Mesh bad = test::octahedron();
  bad.triangles[0][0] = 99;
  EXPECT_THROW(write_mesh(bad, dir.file("bad.obj")), InputError);
  Mesh clash = test::octahedron();
  clash.attributes.push_back({"x", std::vector<float>(6)});
  EXPECT_THROW(write_mesh(clash, dir.file("clash.ply")), InputError);
  EXPECT_THROW(write_mesh(test::octahedron(), dir.file("no/such/dir/m.obj")), IoError);
  std::filesystem::create_directory(dir.file("folder.obj"));
  EXPECT_THROW(write_mesh(test::octahedron(), dir.file("folder.obj")), IoError);
  EXPECT_THROW(write_mesh(test::octahedron(), dir.file("m.xyz")), IoError);
  if (std::filesystem::exists("/dev/full")) {
    // A device that is always full: the failure shows only when the buffer is flushed.
    EXPECT_THROW(write_mesh(test::icosahedron(), "/dev/full", MeshFormat::Obj), IoError);
  }
}

TEST(MeshIo, ReadReportsUnreadablePaths) {
  const test::TempDir dir;
  try {
    read_mesh(dir.file("missing.obj"));
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.obj"), std::string::npos) << e.what();
  }
  std::filesystem::create_directory(dir.file("folder.off"));
  EXPECT_THROW(read_mesh(dir.file("folder.off")), IoError);
  EXPECT_THROW(read_mesh(dir.file("mesh.unknown")), IoError);
}

// A larger mesh (a 300 x 300 grid, 180k triangles) through every format, timed for the record.
TEST(MeshIo, LargeMeshRoundTripsQuickly) {
  const test::TempDir dir;
  const int n = 300;
  Mesh grid;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      grid.positions.push_back(Vec3(i * 0.1, j * 0.1, std::sin(i * 0.05) * std::cos(j * 0.07)));
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const auto v = static_cast<std::uint32_t>(j * n + i);
      grid.triangles.push_back({v, v + 1, v + n + 1});
      grid.triangles.push_back({v, v + n + 1, v + n});
    }
  grid.set_attribute("h", std::vector<float>(grid.vertex_count(), 0.25f));
  for (const auto& [file, format] :
       {std::pair{"g.obj", MeshFormat::Obj}, std::pair{"g.off", MeshFormat::Off},
        std::pair{"a.ply", MeshFormat::PlyAscii}, std::pair{"b.ply", MeshFormat::PlyBinary},
        std::pair{"g.stl", MeshFormat::Stl}}) {
    const auto start = std::chrono::steady_clock::now();
    write_mesh(grid, dir.file(file), format);
    const auto written = std::chrono::steady_clock::now();
    const Mesh back = read_mesh(dir.file(file), format);
    const auto read = std::chrono::steady_clock::now();
    EXPECT_EQ(back.triangle_count(), grid.triangle_count()) << file;
    EXPECT_EQ(back.vertex_count(), grid.vertex_count()) << file;
    const auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count(); };
    RecordProperty(std::string(file) + "_write_ms", std::to_string(ms(written - start)));
    RecordProperty(std::string(file) + "_read_ms", std::to_string(ms(read - written)));
    std::printf("%-6s %9ju bytes  write %6.1f ms  read %6.1f ms\n", file,
                static_cast<std::uintmax_t>(std::filesystem::file_size(dir.file(file))), ms(written - start),
                ms(read - written));
  }
}

}  // namespace
}  // namespace isopatch
