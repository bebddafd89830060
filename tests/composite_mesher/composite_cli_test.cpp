// `isopatch mesh FILE.ipatch` (projection and --method mc), render and analyze against the composite,
// and the exit codes of files that cannot be meshed.
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "error_report.hpp"
#include "run_command.hpp"

namespace isopatch {
namespace {

const std::string kCli = ISOPATCH_CLI;
const std::string kExamples = std::string(ISOPATCH_SOURCE_DIR) + "/examples/";

TEST(CompositeCli, MeshesAFileByProjectionAndByMarchingCubes) {
  const auto dir = test::scratch_dir("composite_cli");
  for (const std::string method : {"projection", "mc"}) {
    const auto out = dir / (method + ".ply");
    const auto r = test::run_command(kCli + " mesh " + kExamples + "pulled_box.ipatch --method " + method +
                                         " --edge-length 0.08 --grid 48 -o " + out.string(),
                                     dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("vertices"), std::string::npos);
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    const TopologyReport t = analyze_topology(read_mesh(out.string()));
    EXPECT_TRUE(t.watertight()) << method;
    EXPECT_TRUE(t.outward_oriented()) << method;
    EXPECT_EQ(t.genus, 0) << method;
  }
  // The same mesh for any thread count.
  const auto one = dir / "one.ply", two = dir / "two.ply";
  ASSERT_EQ(
      test::run_command(kCli + " mesh " + kExamples + "prism.ipatch --threads 1 -q -o " + one.string(), dir)
          .exit_code,
      0);
  ASSERT_EQ(
      test::run_command(kCli + " mesh " + kExamples + "prism.ipatch --threads 2 -q -o " + two.string(), dir)
          .exit_code,
      0);
  EXPECT_EQ(test::read_text(one), test::read_text(two));
  // --refine K refines the composite K times; its statistics say so.
  const auto refined = dir / "refined.ply", stats = dir / "refined.json";
  const auto r = test::run_command(kCli + " mesh " + kExamples + "cube.ipatch --refine 3 -q -o " +
                                       refined.string() + " --stats-json " + stats.string(),
                                   dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(test::read_text(stats).find("\"level\": 3,"), std::string::npos);
  EXPECT_TRUE(analyze_topology(read_mesh(refined.string())).watertight());
}

TEST(CompositeCli, WarnsOfPatchesThatFoldAndRefusesTooShortSetbacks) {
  const auto dir = test::scratch_dir("composite_cli_fold");
  // The tapered prism's face 3 through a reference point deep inside: it folds beside its boundary.
  const auto prism = dir / "prism.ipatch";
  std::ofstream(prism) << test::read_text(kExamples + "tapered_hexagonal_prism.ipatch")
                       << "face 3 centre 0.312285 0.300139 -0.068947\n";
  const auto r = test::run_command(
      kCli + " mesh " + prism.string() + " --edge-length 0.1 -q -o " + (dir / "m.ply").string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: face 3: folds beside side"), std::string::npos) << r.err;
  // A steep pyramid whose setback is too short for its blend radii: refused with one line.
  const auto pyramid = dir / "pyramid.ipatch";
  std::ofstream(pyramid)
      << "ipatch-model 1\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nv 0 0 1\nf 1 4 3 2\n"
         "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\nblend radius 0.12 setback 0.45 facecurve conic\n";
  const auto refused =
      test::run_command(kCli + " mesh " + pyramid.string() + " -q -o " + (dir / "p.ply").string(), dir);
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_NE(refused.err.find("is too short for the blend radii there"), std::string::npos) << refused.err;
}

TEST(CompositeCli, RendersAndAnalysesAgainstTheComposite) {
  const auto dir = test::scratch_dir("composite_cli_fields");
  const auto mesh = dir / "m.ply";
  ASSERT_EQ(test::run_command(
                kCli + " mesh " + kExamples + "cube.ipatch --edge-length 0.2 -q -o " + mesh.string(), dir)
                .exit_code,
            0);
  const auto png = dir / "h.png";
  const auto r = test::run_command(kCli + " render " + mesh.string() + " --show mean-curvature --surface " +
                                       kExamples + "cube.ipatch --size 64x64 -q -o " + png.string(),
                                   dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(png));
  const auto a =
      test::run_command(kCli + " analyze " + mesh.string() + " --surface " + kExamples + "cube.ipatch", dir);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  // Every vertex on the composite: the analysis reports its distance from f = 0.
  EXPECT_NE(a.out.find("distance"), std::string::npos) << a.out;
}

TEST(CompositeCli, ComparesTheMethodsOnAComposite) {
  const auto dir = test::scratch_dir("composite_cli_compare");
  const auto r = test::run_command(kCli + " compare " + kExamples + "cube.ipatch --edge-length 0.3", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* method : {"mc", "mc+fair", "projection"}) EXPECT_NE(r.out.find(method), std::string::npos);
}

TEST(CompositeCli, HonoursARegionAFrameAndTheBase) {
  const auto dir = test::scratch_dir("composite_cli_settings");
  const auto largest_x = [](const Mesh& m) {
    double x = -1e300;
    for (const Vec3& p : m.positions) x = std::max(x, p.x());
    return x;
  };
  const auto mesh = [&](const std::string& name, const std::string& args) {
    const auto out = dir / (name + ".ply");
    const auto r = test::run_command(
        kCli + " mesh " + kExamples + "cube.ipatch -q -o " + out.string() + " " + args, dir);
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
    return read_mesh(out.string());
  };
  // The region x <= -0.2 clips the mesh at its plane (the cube's composite reaches x = 1.73).
  const Mesh clipped = mesh("region", "--region 1,0,0,0.2");
  EXPECT_LE(largest_x(clipped), -0.2 + 1e-9);
  EXPECT_GT(analyze_topology(clipped).boundary_edges, 0u);
  // A frame meshes the piecewise function through a rotated octree: closed, another mesh.
  const Mesh plain = mesh("plain", "");
  const Mesh framed = mesh("frame", "--frame 30,20,10");
  EXPECT_TRUE(analyze_topology(framed).watertight());
  EXPECT_NE(framed.positions, plain.positions);
  // The base: coons is the composite's default, barycentric another base.
  const Mesh coons = mesh("coons", "--remesh 0 --base coons");
  const Mesh automatic = mesh("auto", "--remesh 0");
  const Mesh bary = mesh("bary", "--remesh 0 --base barycentric");
  EXPECT_EQ(coons.positions, automatic.positions);
  EXPECT_NE(bary.positions, coons.positions);
  EXPECT_TRUE(analyze_topology(bary).watertight());
  // The octree's settings mean nothing along the curves: refused, naming the flag, no file written.
  const auto refused = dir / "refused.ply";
  const auto r = test::run_command(
      kCli + " mesh " + kExamples + "cube.ipatch -q --max-depth 5 -o " + refused.string(), dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::InvalidArgument)) << r.err;
  EXPECT_NE(r.err.find("--max-depth"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(refused));
  // Through the partition (a frame) the octree reads them.
  EXPECT_TRUE(analyze_topology(mesh("framed_depth", "--frame 30,20,10 --max-depth 7")).watertight());
}

TEST(CompositeCli, RefusesBadFilesWithOneLineAndAnExitCode) {
  const auto dir = test::scratch_dir("composite_cli_bad");
  const auto bad = dir / "bad.ipatch";
  std::ofstream(bad) << "ipatch-model 1\nv 0 0 0\nv 1 0 0\nf 1 2\n";
  const auto out = (dir / "o.ply").string();
  auto r = test::run_command(kCli + " mesh " + bad.string() + " -o " + out, dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::InvalidArgument)) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("bad.ipatch:4"), std::string::npos) << r.err;
  std::ofstream(bad) << "ipatch-model 1\nv nan 0 0\n";
  r = test::run_command(kCli + " mesh " + bad.string() + " -o " + out, dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::InvalidArgument)) << r.err;
  r = test::run_command(kCli + " mesh " + (dir / "missing.ipatch").string() + " -o " + out, dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::Io)) << r.err;
  r = test::run_command(kCli + " mesh " + kExamples + "cube.ipatch --param a=1 -o " + out, dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::InvalidArgument)) << r.err;
  r = test::run_command(kCli + " mesh " + kExamples + "cube.ipatch --edge-length -1 -o " + out, dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::InvalidArgument)) << r.err;
  r = test::run_command(kCli + " mesh " + kExamples + "cube.ipatch --max-evaluations 100 -o " + out, dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::Limit)) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace isopatch
