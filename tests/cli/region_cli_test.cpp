// The command line's --region and --frame (issue 21): a region from text or a file, its boundary on
// its planes, a rotated frame, and one-line errors with their exit codes for bad regions and frames.
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "error_report.hpp"
#include "run_command.hpp"

namespace isopatch {
namespace {

const std::string kRegionCli = ISOPATCH_CLI;

TEST(RegionCli, RegionFromAFileCutsTheSphereOnItsPlanes) {
  const auto dir = test::scratch_dir("cli_region");
  const auto planes = dir / "region.txt";
  std::ofstream(planes) << "# two half-spaces: z <= 0.3 and x + y <= 0.5\n0,0,1,-0.3\n\n1,1,0,-0.5\n";
  const auto out = dir / "cut.ply";
  const auto r = test::run_command(kRegionCli + " mesh sphere --box -1.2,-1.2,-1.2,1.2,1.2,1.2 --region @" +
                                       planes.string() + " -q -o " + out.string(),
                                   dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Mesh mesh = read_mesh(out.string());
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 1);  // a sphere less one cap: a disc
  EXPECT_GT(t.boundary_edges, 0u);
  for (const Vec3& p : mesh.positions) {
    EXPECT_LE(p.z(), 0.3 + 1e-12);
    EXPECT_LE(p.x() + p.y(), 0.5 + 1e-12);
  }
}

TEST(RegionCli, RotatedFrameMeshesTheTorusClosed) {
  const auto dir = test::scratch_dir("cli_frame");
  const auto out = dir / "torus.ply";
  const auto r = test::run_command(kRegionCli + " mesh torus --frame 30,20,10 -q -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TopologyReport t = analyze_topology(read_mesh(out.string()));
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.outward_oriented());
  EXPECT_EQ(t.genus, 1);
}

// A formula needs no --box when the region is bounded; a catalogue surface with an unbounded region
// and no --box is cut inside its own box.
TEST(RegionCli, BoundedRegionStandsForTheBoxAndCatalogueBoxesHoldUnboundedOnes) {
  const auto dir = test::scratch_dir("cli_region_box");
  const auto out = dir / "m.ply";
  const std::string cube = "1,0,0,-2;-1,0,0,-2;0,1,0,-2;0,-1,0,-2;0,0,-1,-2";
  auto r = test::run_command(
      kRegionCli + " mesh \"x^2+y^2+z^2-1\" --region \"0,0,1,0;" + cube + "\" -q -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  TopologyReport t = analyze_topology(read_mesh(out.string()));
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 1);  // the lower half sphere: a disc
  struct Case {
    std::string surface, region;
    int euler;
  };
  for (const Case& c : {Case{"torus", "0,0,1,0.1", 0}, Case{"sphere", "0,0,1,0", 1}}) {
    r = test::run_command(
        kRegionCli + " mesh " + c.surface + " --region " + c.region + " -q -o " + out.string(), dir);
    ASSERT_EQ(r.exit_code, 0) << c.surface << "\n" << r.err;
    t = analyze_topology(read_mesh(out.string()));
    EXPECT_EQ(t.components.size(), 1u) << c.surface;
    EXPECT_EQ(t.euler_characteristic, c.euler) << c.surface;
    EXPECT_GT(t.boundary_edges, 0u) << c.surface;
  }
}

TEST(RegionCli, BadRegionsAndFramesGiveOneLineAndTheirExitCode) {
  const auto dir = test::scratch_dir("cli_region_bad");
  const std::string out = " -o " + (dir / "m.ply").string();
  const std::string box = " --box -1.2,-1.2,-1.2,1.2,1.2,1.2";
  struct Case {
    std::string args;
    ErrorKind kind;
    std::string says;
  };
  const std::vector<Case> cases = {
      {"mesh sphere --region 0,0,1" + box + out, ErrorKind::InvalidArgument, "not four numbers"},
      {"mesh sphere --region 0,0,1,x" + box + out, ErrorKind::InvalidArgument, "plane 1"},
      {"mesh sphere --region \"0,0,1,0;0,0,0,1\"" + box + out, ErrorKind::InvalidArgument, "plane 2"},
      {"mesh sphere --region \";\"" + box + out, ErrorKind::InvalidArgument, "no plane"},
      {"mesh \"x^2+y^2+z^2-1\" --region 0,0,1,0" + out, ErrorKind::InvalidArgument, "unbounded"},
      {"mesh \"x^2+y^2+z^2-1\"" + out, ErrorKind::InvalidArgument, "needs a box"},
      {"mesh sphere --region 0,0,1,5" + out, ErrorKind::InvalidArgument, "does not meet"},
      {"mesh sphere --region \"0,0,1,0;0,0,-1,0.5\"" + box + out, ErrorKind::InvalidArgument, "--region"},
      {"mesh sphere --region 0,0,1,0 --method mc" + box + out, ErrorKind::InvalidArgument, "--method"},
      {"mesh sphere --region @" + (dir / "missing.txt").string() + box + out, ErrorKind::Io, "cannot read"},
      {"mesh sphere --frame 30,20" + out, ErrorKind::InvalidArgument, "AZ,EL,ROLL"},
      {"mesh sphere --frame 30,20,10 --method mc" + out, ErrorKind::InvalidArgument, "--method"},
      {"mesh sphere --frame 30,nan,1" + out, ErrorKind::InvalidArgument, "frame"},
  };
  for (const Case& c : cases) {
    const auto r = test::run_command(kRegionCli + " " + c.args, dir);
    EXPECT_EQ(r.exit_code, cli::exit_code(c.kind)) << c.args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("isopatch: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
  }
}

// A plane nearly tangent to the sphere cuts a hole of radius 0.014, under half an edge (issue 35): the
// sizes shrink there and a warning line says where and how many vertices it added (also with -q);
// --uniform keeps one size and says nothing of it.
TEST(RegionCli, NarrowCutRefinedWithAWarningUnlessUniform) {
  const auto dir = test::scratch_dir("cli_cut_features");
  const auto out = dir / "hole.ply";
  const std::string mesh =
      kRegionCli + " mesh sphere --box -1.2,-1.2,-1.2,1.2,1.2,1.2 --region 0,0,1,-0.9999 -q -o ";
  auto r = test::run_command(mesh + out.string() + " --stats-json " + (dir / "s.json").string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: sizes refined around "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("vertices added"), std::string::npos) << r.err;
  const auto stats = nlohmann::json::parse(test::read_text(dir / "s.json"));
  ASSERT_TRUE(stats.contains("local_sizes"));
  const auto& sizes = stats["local_sizes"];
  EXPECT_GT(sizes["sources"].get<double>(), 0.0);
  EXPECT_GT(sizes["added_vertices"].get<double>(), 0.0);
  EXPECT_LT(sizes["smallest_size"].get<double>(), 0.5 * 2.4 / 64);  // under half the default edge
  for (const char* z : {"extent_lo_z", "extent_hi_z"})
    EXPECT_NEAR(sizes[z].get<double>(), 0.9999, 1e-9);  // on the cutting plane
  EXPECT_LE(sizes["extent_hi_x"].get<double>(),
            std::sqrt(1.0 - 0.9999 * 0.9999) + 1e-9);  // the hole's circle
  r = test::run_command(mesh + out.string() + " --uniform", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("features narrower than an edge"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace isopatch
