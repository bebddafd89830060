// The writers stream: a file is written in chunks as the encoder makes them, so the memory a writer
// adds to the mesh is bounded (one chunk, and for glTF the normals), not the size of the file; the file
// holds exactly the bytes of encode_mesh; a failed write leaves no partial file.
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include "mesh/byte_sink.hpp"
#include "mesh/io_util.hpp"
#include "mesh/mesh_formats.hpp"
#include "mesh_fixtures.hpp"

namespace isopatch {
namespace {

/// A bumpy n x n grid of vertices, two triangles per cell, with one attribute: about 24 MB of ASCII
/// OBJ at n = 600.
Mesh large_grid(int n) {
  Mesh m;
  std::vector<float> field;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = i / (n - 1.0), y = j / (n - 1.0);
      m.positions.emplace_back(x, y, 0.1 * std::sin(9.0 * x) * std::cos(7.0 * y));
      field.push_back(static_cast<float>(x * y));
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const auto v = static_cast<std::uint32_t>(j * n + i), w = static_cast<std::uint32_t>(n);
      m.triangles.push_back({v, v + 1, v + w + 1});
      m.triangles.push_back({v, v + w + 1, v + w});
    }
  m.set_attribute("field", field);
  return m;
}

std::string file_bytes(const std::string& path) {
  return io::load_file(path);
}

TEST(StreamingWriters, HoldAChunkNotTheFileAndWriteTheBytesOfEncodeMesh) {
  const test::TempDir dir;
  const Mesh mesh = large_grid(600);
  const std::vector<Vec3> colours(mesh.vertex_count(), Vec3(0.2, 0.4, 0.6));
  for (const MeshFormat format : {MeshFormat::Obj, MeshFormat::PlyAscii, MeshFormat::PlyBinary,
                                  MeshFormat::Off, MeshFormat::Stl, MeshFormat::Glb, MeshFormat::ThreeMf}) {
    SCOPED_TRACE(static_cast<int>(format));
    const std::vector<Vec3>& c = format == MeshFormat::Glb ? colours : std::vector<Vec3>{};
    const std::string path = dir.file("streamed.bin");
    std::FILE* file = std::fopen(path.c_str(), "wb");
    ASSERT_NE(file, nullptr);
    io::ByteSink sink(file, path);
    io::encode_to(mesh, format, c, sink);
    sink.flush();
    ASSERT_EQ(std::fclose(file), 0);
    const std::string expected = encode_mesh(mesh, format, c);
    EXPECT_GT(expected.size(), 4 * io::ByteSink::kChunk) << "a file of several chunks";
    EXPECT_EQ(sink.written(), expected.size());
    // What the writer held besides the mesh: one chunk and the largest single piece appended to it (a
    // line of text, a compressed piece of the 3MF package, the glTF JSON).
    EXPECT_LE(sink.largest_held(), io::ByteSink::kChunk + (std::size_t{1} << 16));
    EXPECT_TRUE(file_bytes(path) == expected);
    // write_mesh goes the same way.
    write_mesh(mesh, path, format, c);
    EXPECT_TRUE(file_bytes(path) == expected);
  }
}

TEST(StreamingWriters, AFailedWriteLeavesNoPartialFile) {
  const test::TempDir dir;
  const std::string path = dir.file("part.ply");
  Mesh clash = test::octahedron();
  clash.attributes.push_back(
      {"x", std::vector<float>(6)});  // refused by the PLY encoder, after the file is made
  EXPECT_THROW(write_mesh(clash, path), InputError);
  EXPECT_FALSE(std::filesystem::exists(path));
  if (std::filesystem::exists("/dev/full")) {
    EXPECT_THROW(write_mesh(large_grid(200), "/dev/full", MeshFormat::PlyBinary), IoError);
    EXPECT_TRUE(std::filesystem::exists("/dev/full")) << "a device is never removed";
  }
}

TEST(StreamingWriters, ACancelledWriteStopsAtTheNextChunkAndLeavesThePreviousFile) {
  const Mesh mesh = large_grid(300);
  // A flag set while the first chunk goes out stops the writer before the second.
  std::atomic<bool> cancel{false};
  int chunks = 0;
  io::ByteSink sink([&](const char*, std::size_t) {
    ++chunks;
    cancel.store(true);
  });
  sink.stop_when(&cancel);
  EXPECT_THROW(io::encode_to(mesh, MeshFormat::Obj, {}, sink), LimitError);
  EXPECT_EQ(chunks, 1);
  // write_mesh: no temporary file left, the file there before as it was, the error names the budget.
  const test::TempDir dir;
  const std::string path = dir.file("kept.ply");
  write_whole_file(path, "before");
  try {
    write_mesh(mesh, path, MeshFormat::PlyBinary, {}, &cancel);
    ADD_FAILURE() << "a cancelled write returned";
  } catch (const LimitError& e) {
    EXPECT_EQ(e.setting(), "cancel");
    EXPECT_NE(std::string(e.what()).find("kept.ply"), std::string::npos) << e.what();
  }
  EXPECT_EQ(file_bytes(path), "before");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.file("")), {}), 1);
  cancel.store(false);
  write_mesh(mesh, path, MeshFormat::PlyBinary, {}, &cancel);
  EXPECT_TRUE(file_bytes(path) == encode_mesh(mesh, MeshFormat::PlyBinary));
}

}  // namespace
}  // namespace isopatch
