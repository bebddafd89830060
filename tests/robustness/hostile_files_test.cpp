// Hostile mesh files given to `isopatch analyze`: truncated, lying, garbage. The tool must exit with the
// Io exit code and exactly one line on stderr (the reader-level cases are in tests/mesh).
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "error_report.hpp"
#include "run_command.hpp"

namespace isopatch {
namespace {

const std::string kCli = ISOPATCH_CLI;

struct Hostile {
  std::string name;   ///< file name (the extension picks the reader)
  std::string bytes;  ///< contents
};

template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);  // little-endian hosts
}

Mesh tetrahedron() {
  Mesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

std::vector<Hostile> hostile_files() {
  std::vector<Hostile> files;
  const Mesh tet = tetrahedron();
  // Truncated valid files: cut in the middle of the data.
  for (const auto& [ext, format] :
       {std::pair{".obj", MeshFormat::Obj}, std::pair{".off", MeshFormat::Off},
        std::pair{".stl", MeshFormat::Stl}, std::pair{".ply", MeshFormat::PlyBinary}}) {
    const std::string full = encode_mesh(tet, format);
    files.push_back({std::string("truncated") + ext, full.substr(0, full.size() * 2 / 3)});
  }
  {
    const std::string full = encode_mesh(tet, MeshFormat::PlyAscii);
    files.push_back({"truncated_ascii.ply", full.substr(0, full.size() - 12)});
  }
  // Lying headers: counts far beyond the bytes.
  files.push_back(
      {"lying.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\n"
       "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
       "end_header\n" +
           std::string(24, '\0')});
  files.push_back({"lying.off", "OFF\n1000000000 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"});
  {
    std::string stl(80, ' ');
    put<std::uint32_t>(stl, 4000000000u);  // triangles claimed
    stl += std::string(50, '\0');          // one triangle's worth
    files.push_back({"lying.stl", stl});
  }
  files.push_back({"index_out_of_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n"});
  files.push_back({"nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"});
  files.push_back({"huge_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n100000 0 1 2\n"});
  // Garbage.
  std::string garbage;
  std::uint32_t state = 12345;
  for (int i = 0; i < 4096; ++i) {
    state = state * 1664525u + 1013904223u;
    garbage.push_back(static_cast<char>(state >> 24));
  }
  for (const char* ext : {".obj", ".ply", ".off", ".stl"})
    files.push_back({std::string("garbage") + ext, garbage});
  files.push_back({"empty.ply", ""});
  files.push_back({"empty.off", ""});
  files.push_back(
      {"header_only.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n"});
  files.push_back({"text.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\nendloop\n"});
  return files;
}

int count_lines(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

TEST(HostileFiles, AnalyzeExitsWithIoCodeAndOneLine) {
  const auto dir = test::scratch_dir("robust_hostile");
  for (const Hostile& h : hostile_files()) {
    SCOPED_TRACE(h.name);
    const auto path = dir / h.name;
    {
      std::ofstream out(path, std::ios::binary);
      out << h.bytes;
    }
    const auto r = test::run_command(kCli + " analyze " + path.string(), dir);
    EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::Io)) << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(h.name), std::string::npos) << "the message names the file: " << r.err;
  }
}

TEST(HostileFiles, MissingFileAndDirectory) {
  const auto dir = test::scratch_dir("robust_missing");
  for (const std::string& path : {(dir / "missing.obj").string(), dir.string() + "/"}) {
    SCOPED_TRACE(path);
    const auto r = test::run_command(kCli + " analyze " + path, dir);
    EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::Io)) << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
  }
}

}  // namespace
}  // namespace isopatch
