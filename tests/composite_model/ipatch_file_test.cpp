// The .ipatch reader: the note's level-1 text accepted as is, the options, and every kind of malformed
// or hostile text refused with "<source>:<line>:<column>: ..." on one line.
#include "composite_model/ipatch_file.hpp"
#include "composite_model/composite_checks.hpp"

#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace isopatch {
namespace {

const std::string kCube = R"(# cube -> sphere of radius sqrt(3) (exact test)
ipatch-model 1
v -1 -1 -1
v -1 -1  1
v -1  1 -1
v -1  1  1
v  1 -1 -1
v  1 -1  1
v  1  1 -1
v  1  1  1
# optional per vertex: vn i nx ny nz    (default: normalized sum of adjacent face normals)
f 1 2 4 3
f 5 7 8 6
f 1 5 6 2
f 3 4 8 7
f 1 3 7 5
f 2 6 8 4
)";

/// The message parse_ipatch throws for `text`, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_ipatch(text, "t.ipatch");
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_EQ(m.rfind("t.ipatch:", 0), 0u) << m;
    return m;
  }
  return "";
}

/// `text` with line `line` (1-based) replaced.
std::string with_line(const std::string& text, int line, const std::string& replacement) {
  std::string out;
  int n = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    ++n;
    out += (n == line ? replacement : text.substr(pos, end - pos)) + "\n";
    pos = end + 1;
  }
  return out;
}

TEST(IpatchFile, TheNotesLevelOneCubeIsAcceptedAsIs) {
  const Composite c = parse_ipatch(kCube, "cube.ipatch");
  EXPECT_EQ(c.patches.size(), 6u);
  EXPECT_EQ(c.curves.size(), 12u);
  EXPECT_NO_THROW(check_composite_closed(c));
  EXPECT_TRUE(c.box.valid());
  EXPECT_EQ(c.name, "cube.ipatch");
}

TEST(IpatchFile, OptionsAreRead) {
  const std::string text =
      kCube + "name my cube\nvn 8 1 1.1 0.9\nedge 1 2 weight 0.7\nface 2 centre 1.7 0 0 d 1 1 2 1\n";
  const Composite c = parse_ipatch(text, "cube.ipatch");
  EXPECT_EQ(c.name, "my cube");
  EXPECT_LT(std::abs(c.patches[1].surface->value(Vec3(1.7, 0, 0))), 1e-13);
  const Composite b = parse_ipatch(
      "ipatch-model 1\r\nsolid box 0 0 0 2 1 1\r\nblend radius 0.2 setback 0.45 facecurve planar\r\n"
      "vertex 8 setback 0.4\r\nedge 7 8 radius 0.15\r\n",
      "b.ipatch");
  EXPECT_EQ(b.patches.size(), 26u);
}

TEST(IpatchFile, MalformedLinesAreRefusedWithLineAndColumn) {
  EXPECT_EQ(error_of(""), "t.ipatch:1:1: empty file: expected the header 'ipatch-model 1'");
  EXPECT_EQ(error_of("# only a comment\n"), "t.ipatch:1:1: empty file: expected the header 'ipatch-model 1'");
  EXPECT_EQ(error_of(with_line(kCube, 2, "v 1 2 3")), "t.ipatch:2:1: expected the header 'ipatch-model 1'");
  EXPECT_NE(error_of(with_line(kCube, 2, "ipatch-model 2")).find("t.ipatch:2:14: unsupported"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 5, "  w 1 2 3")).find("t.ipatch:5:3: unknown keyword 'w'"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 5, "v -1 nan 1")).find("t.ipatch:5:6: numbers must be finite"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 5, "v -1 inf 1")).find("t.ipatch:5:6: numbers must be finite"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 5, "v -1 1e400 1")).find("t.ipatch:5:6: number out of range"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 5, "v -1 2e6 1")).find("t.ipatch:5:6: numbers must not exceed"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 5, "v -1 1x 1")).find("t.ipatch:5:6: expected a number, found '1x'"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 5, "v -1 1")).find("t.ipatch:5:7: missing"), std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 5, "v -1 1 1 1")).find("t.ipatch:5:10: unexpected '1'"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 12, "f 1 2 4 9")).find("t.ipatch:12:9: vertex 9 does not exist"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 12, "f 1 2 0 3")).find("t.ipatch:12:7: expected vertex"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 12, "f 1 2 -4 3")).find("t.ipatch:12:7: expected vertex"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 12, "f 1 2")).find("t.ipatch:12:6: missing vertex"), std::string::npos);
  EXPECT_NE(error_of(kCube + "edge 1 8 weight 0.5\n").find("t.ipatch:18:6: vertices 1 and 8 are not joined"),
            std::string::npos);
  EXPECT_NE(error_of(kCube + "edge 1 2 weight -1\n").find("t.ipatch:18:17: a curve weight must be positive"),
            std::string::npos);
  EXPECT_NE(error_of(kCube + "face 7 centre 0 0 0\n").find("t.ipatch:18:6: face 7 does not exist"),
            std::string::npos);
  EXPECT_NE(error_of(kCube + "face 1 centre 0 0 0 d 1 1\n").find("t.ipatch:18:21: face 1 has 4 sides"),
            std::string::npos);
  EXPECT_NE(error_of(kCube + "edge 1 2 radius 0.2\n").find("need a 'blend' line"), std::string::npos);
  EXPECT_NE(error_of("ipatch-model 1\nsolid box 0 0 0 1 1\n").find("t.ipatch:2:"), std::string::npos);
  EXPECT_NE(error_of("ipatch-model 1\nsolid box 0 0 0 1 -1 1\n").find("lo < hi"), std::string::npos);
  EXPECT_NE(error_of("ipatch-model 1\nsolid box 0 0 0 1 1 1\nblend radius 0.2 setback 0.5 facecurve round\n")
                .find("t.ipatch:3:40: facecurve is"),
            std::string::npos);
}

TEST(IpatchFile, BadTopologyNamesTheLineToBlame) {
  EXPECT_NE(error_of(with_line(kCube, 14, "f 2 6 5 1")).find("t.ipatch:14:1: face 3 runs along edge 6-5"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 12, "f 1 2 2 3")).find("t.ipatch:12:1: face 1 uses vertex 2 twice"),
            std::string::npos);
  EXPECT_NE(error_of(with_line(kCube, 17, "")).find("the polyhedron is open"), std::string::npos);
  EXPECT_NE(error_of(kCube + "v 5 5 5\n").find("t.ipatch:18:1: vertex 9 is used by no face"),
            std::string::npos);
  EXPECT_NE(error_of(kCube + "f 1 2 4 3\n").find("t.ipatch:"), std::string::npos);
  // A face of collinear points.
  EXPECT_NE(
      error_of("ipatch-model 1\nv 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n")
          .find("t.ipatch:6:1: face 1 has no area"),
      std::string::npos);
}

TEST(IpatchFile, HostileSizesAreRefused) {
  std::string many = "ipatch-model 1\n";
  for (std::size_t i = 0; i <= kMaxIpatchVertices; ++i) many += "v 0 0 0\n";
  EXPECT_NE(error_of(many).find("too many vertices"), std::string::npos);
  std::string big(kMaxIpatchBytes + 1, ' ');
  EXPECT_NE(error_of(big).find("larger than"), std::string::npos);
  EXPECT_NE(error_of(std::string("ipatch-model 1\nv 0 0 0\0\n", 24)).find("t.ipatch:"), std::string::npos);
  std::string long_face = "ipatch-model 1\nf";
  for (int i = 0; i < 40; ++i) long_face += " 1";
  EXPECT_NE(error_of(long_face).find("at most 16 vertices"), std::string::npos);
}

TEST(IpatchFile, GeometryTheConstructionRefusesNamesTheFile) {
  // A box blended with a setback smaller than the radius needs.
  const std::string m = error_of("ipatch-model 1\nsolid box -1 -1 -1 1 1 1\nblend radius 0.3 setback 0.2\n");
  EXPECT_NE(m.find("t.ipatch: vertex 1: the setback"), std::string::npos) << m;
}

TEST(IpatchFile, ReadIpatchReadsFilesAndRefusesMissingOnes) {
  const std::string path = std::string(ISOPATCH_BINARY_DIR) + "/ipatch_file_test_cube.ipatch";
  {
    std::ofstream out(path);
    out << kCube;
  }
  EXPECT_EQ(read_ipatch(path).patches.size(), 6u);
  EXPECT_THROW(read_ipatch(path + ".missing"), IoError);
  EXPECT_THROW(read_ipatch(std::string(ISOPATCH_BINARY_DIR)), IoError);  // a directory
}

}  // namespace
}  // namespace isopatch
