// End-to-end tests of the isopatch tool: real command lines, outputs checked with the project's metrics.
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "error_report.hpp"
#include "run_command.hpp"

namespace isopatch {
namespace {

const std::string kCli = ISOPATCH_CLI;

int count_lines(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

TEST(Cli, MeshesCatalogueSurfaceWithMarchingCubes) {
  const auto dir = test::scratch_dir("cli_mc");
  const auto out = dir / "torus.ply";
  const auto r = test::run_command(kCli + " mesh torus -o " + out.string() + " --method mc --grid 48", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("vertices"), std::string::npos);
  EXPECT_NE(r.out.find("time"), std::string::npos);
  const Mesh mesh = read_mesh(out.string());
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.manifold());
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_TRUE(t.outward_oriented());
  EXPECT_EQ(t.genus, 1);
}

TEST(Cli, MeshesFormulaWithBox) {
  const auto dir = test::scratch_dir("cli_formula");
  const auto out = dir / "s.ply";
  const auto r = test::run_command(
      kCli + " mesh \"x^2+y^2+z^2-1\" --box -1.3,-1.2,-1.1,1.2,1.3,1.25 --method mc --grid 40 -o " +
          out.string(),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TopologyReport t = analyze_topology(read_mesh(out.string()));
  EXPECT_TRUE(t.watertight());
  EXPECT_EQ(t.genus, 0);
}

TEST(Cli, StoresVertexRolesAndPrintsStageTimes) {
  // --vertex-roles keeps what made each vertex (corners, seams, interiors of the raw projection mesh);
  // the summary names the stages with their times and the thread count.
  const auto dir = test::scratch_dir("cli_roles");
  const auto out = dir / "raw.ply";
  const auto r =
      test::run_command(kCli + " mesh genus2 --remesh 0 --vertex-roles --threads 2 -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("stage      partition"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stage      patches"), std::string::npos);
  EXPECT_NE(r.out.find("threads    2"), std::string::npos);
  EXPECT_NE(r.out.find("defect_seam_under_20"), std::string::npos);
  const Mesh mesh = read_mesh(out.string());
  const VertexAttribute* role = nullptr;
  for (const VertexAttribute& a : mesh.attributes)
    if (a.name == "role") role = &a;
  ASSERT_NE(role, nullptr);
  ASSERT_EQ(role->values.size(), mesh.vertex_count());
  std::size_t counts[5] = {};
  for (const float v : role->values) {
    ASSERT_TRUE(v >= 0.0f && v <= 4.0f && v == std::floor(v)) << v;
    ++counts[static_cast<int>(v)];
  }
  EXPECT_GT(counts[0], 0u);  // corners
  EXPECT_GT(counts[1], 0u);  // seams
  EXPECT_GT(counts[2], 0u);  // patch interiors
}

TEST(Cli, ListsSurfaces) {
  const auto dir = test::scratch_dir("cli_surfaces");
  const auto r = test::run_command(kCli + " surfaces", dir);
  ASSERT_EQ(r.exit_code, 0);
  for (const char* name : {"sphere", "torus", "tanglecube", "genus2", "chmutov6", "gyroid", "heart"})
    EXPECT_NE(r.out.find(name), std::string::npos) << name;
}

struct BadCase {
  std::string args;
  ErrorKind kind;
};

TEST(Cli, BadInputGivesOneLineAndDistinctExitCode) {
  const auto dir = test::scratch_dir("cli_bad");
  const std::string ok_out = " -o " + (dir / "m.ply").string();
  const std::vector<BadCase> cases = {
      {"mesh tours --method mc" + ok_out, ErrorKind::UnknownSurface},
      {"mesh torus --method mc --box 1,2,3" + ok_out, ErrorKind::InvalidArgument},
      {"mesh torus --method mc --box 0,0,0,1,1,0" + ok_out, ErrorKind::InvalidArgument},
      {"mesh torus --method mc --grid 100000000" + ok_out, ErrorKind::InvalidArgument},
      {"mesh torus --method mc --grid 0" + ok_out, ErrorKind::InvalidArgument},
      {"mesh torus --valence-search -1" + ok_out, ErrorKind::InvalidArgument},
      {"mesh torus --workers 3" + ok_out, ErrorKind::InvalidArgument},  // a blocked run's flag alone
      {"mesh torus --out-dir " + dir.string() + ok_out, ErrorKind::InvalidArgument},
      {"mesh torus --valence-search 20000" + ok_out, ErrorKind::InvalidArgument},
      {"mesh torus --curvature-sweeps -1" + ok_out, ErrorKind::InvalidArgument},
      {"mesh torus --curvature-sweeps 1001" + ok_out, ErrorKind::InvalidArgument},
      {"mesh torus --max-cell-curvature -1" + ok_out, ErrorKind::InvalidArgument},
      {"mesh torus --max-cell-curvature nan" + ok_out, ErrorKind::InvalidArgument},
      {"mesh torus --method mc -o /nonexistent/folder/m.ply", ErrorKind::Io},
      {"mesh torus --method mc -o " + (dir / "m.xyz").string(), ErrorKind::Io},
      {"mesh \"x^^2\" --box -1,-1,-1,1,1,1 --method mc" + ok_out, ErrorKind::Parse},
      {"mesh \"x^2+y^2+z^2+1\" --box -1,-1,-1,1,1,1 --method mc" + ok_out, ErrorKind::NoSurface},
      {"mesh \"sqrt(x)+y\" --box -1,-1,-1,1,1,1 --method mc" + ok_out, ErrorKind::Evaluation},
      {"mesh \"(x^2+y^2+z^2-1)^3\" --box -2,-2,-2,2,2,2" + ok_out, ErrorKind::SingularSurface},
      {"mesh @" + (dir / "missing.txt").string() + " --box -1,-1,-1,1,1,1 --method mc" + ok_out,
       ErrorKind::Io},
  };
  for (const BadCase& c : cases) {
    const auto r = test::run_command(kCli + " " + c.args, dir);
    EXPECT_EQ(r.exit_code, cli::exit_code(c.kind)) << c.args << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << c.args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("isopatch: ", 0), 0u) << r.err;
  }
}

TEST(Cli, ASettingOutOfRangeNamesItsFlag) {
  // The library names the Settings field (Error::setting()); the tool names the flag that sets it.
  const auto dir = test::scratch_dir("cli_flags");
  const std::string out = " -o " + (dir / "m.ply").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--edge-length -1", "--edge-length"},
      {"--max-error 0", "--max-error"},
      {"--resolution 65", "--resolution"},
      {"--min-depth 9 --max-depth 3", "--min-depth"},
      {"--max-depth 13", "--max-depth"},
      {"--refinement-levels 13", "--refinement-levels"},
      {"--max-ray-angle 95", "--max-ray-angle"},
      {"--method mc --grid 0", "--grid"},
      {"--method mc --fair 20000", "--fair"},
      {"--remesh 101", "--remesh"},
      {"--valence-search -1", "--valence-search"},
      {"--time-limit -1", "--time-limit"},
      {"--method mc --grid-offset 1", "--grid-offset"},
  };
  const auto help = test::run_command(kCli + " mesh --help", dir);
  for (const auto& [args, flag] : cases) {
    const auto r = test::run_command(kCli + " mesh torus " + args + out, dir);
    EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::InvalidArgument)) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("(" + flag + ")"), std::string::npos) << args << "\n" << r.err;
    EXPECT_NE(help.out.find(flag + " "), std::string::npos) << flag << " is not a flag of isopatch mesh";
  }
}

TEST(Cli, ParseErrorPointsAtTheColumn) {
  const auto dir = test::scratch_dir("cli_parse");
  const auto r = test::run_command(
      kCli + " mesh \"x^^2\" --box -1,-1,-1,1,1,1 --method mc -o " + (dir / "m.ply").string(), dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::Parse));
  EXPECT_NE(r.err.find("column 3"), std::string::npos) << r.err;
}

TEST(Cli, UsageErrorsExitWithTwo) {
  const auto dir = test::scratch_dir("cli_usage");
  EXPECT_EQ(test::run_command(kCli, dir).exit_code, 2);
  EXPECT_EQ(test::run_command(kCli + " mesh torus", dir).exit_code, 2);  // no -o
  EXPECT_EQ(test::run_command(kCli + " frobnicate", dir).exit_code, 2);
}

TEST(Cli, MeshWithFieldsStoresCurvatureAttributes) {
  const auto dir = test::scratch_dir("cli_fields");
  const auto out = dir / "t.ply";
  const auto r = test::run_command(kCli + " mesh torus --edge-length 0.1 --fields -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Mesh mesh = read_mesh(out.string());
  for (const char* name : {"mean_curvature", "mean_curvature_exact", "gaussian_curvature",
                           "gaussian_curvature_exact", "distance"})
    EXPECT_NE(mesh.find_attribute(name), nullptr) << name;
}

TEST(Cli, CompareTorusPrintsTheTable) {
  const auto dir = test::scratch_dir("cli_compare");
  const auto r =
      test::run_command(kCli + " compare torus --edge-length 0.12 --images " + (dir / "img").string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* word : {"method", "mc+fair", "projection", "H nRMS", "val6"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
  EXPECT_TRUE(std::filesystem::exists(dir / "img" / "compare_level0.png"));
}

TEST(Cli, ProjectionIsTheDefaultMethod) {
  const auto dir = test::scratch_dir("cli_projection");
  const auto out = dir / "g.ply";
  const auto r =
      test::run_command(kCli + " mesh genus2 --edge-length 0.05 --base coons -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("projection"), std::string::npos);
  EXPECT_NE(r.out.find("patches_"), std::string::npos);
  const TopologyReport t = analyze_topology(read_mesh(out.string()));
  EXPECT_TRUE(t.watertight());
  EXPECT_EQ(t.genus, 2);
}

/// The last "done/total <unit>" state drawn on a progress line, or {-1, -1}. (Parsed by hand: GCC 12
/// warns inside std::regex under the sanitizer build.)
std::pair<long, long> last_progress(const std::string& err, const std::string& unit) {
  std::pair<long, long> last{-1, -1};
  const std::string suffix = " " + unit;
  for (std::size_t at = err.find(suffix); at != std::string::npos; at = err.find(suffix, at + 1)) {
    std::size_t b = at;  // digits of total end at `at`
    while (b > 0 && std::isdigit(static_cast<unsigned char>(err[b - 1]))) --b;
    if (b == at || b == 0 || err[b - 1] != '/') continue;
    std::size_t a = b - 1;
    while (a > 0 && std::isdigit(static_cast<unsigned char>(err[a - 1]))) --a;
    if (a == b - 1) continue;
    last = {std::stol(err.substr(a, b - 1 - a)), std::stol(err.substr(b, at - b))};
  }
  return last;
}

TEST(Cli, ProgressFlagDrawsOneUpdatingLineOnStderr) {
  const auto dir = test::scratch_dir("cli_progress");
  const auto out = dir / "torus.ply";
  const auto r =
      test::run_command(kCli + " mesh torus --method mc --grid 48 --progress -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("isopatch: mc "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find('\r'), std::string::npos);  // updates overwrite the line
  EXPECT_EQ(count_lines(r.err), 1) << r.err;       // ... which is ended once
  EXPECT_EQ(r.err.back(), '\n');
  const auto [done, total] = last_progress(r.err, "slabs");
  EXPECT_GT(total, 0) << r.err;
  EXPECT_EQ(done, total) << r.err;  // the final state is always drawn
  EXPECT_NE(r.out.find("vertices"), std::string::npos);
  const TopologyReport t = analyze_topology(read_mesh(out.string()));  // the mesh is still written
  EXPECT_TRUE(t.watertight());
  EXPECT_EQ(t.genus, 1);

  // Projection, quiet: nothing on stdout, the progress line on stderr.
  const auto sphere = dir / "sphere.ply";
  const auto q =
      test::run_command(kCli + " mesh sphere --edge-length 0.2 --progress -q -o " + sphere.string(), dir);
  ASSERT_EQ(q.exit_code, 0) << q.err;
  EXPECT_TRUE(q.out.empty()) << q.out;
  EXPECT_NE(q.err.find("isopatch: projection "), std::string::npos) << q.err;
  EXPECT_GT(last_progress(q.err, "partition rounds").second, 0) << q.err;
  EXPECT_GT(read_mesh(sphere.string()).vertex_count(), 0u);
}

TEST(Cli, ProgressOnlyOnATerminalByDefault) {
  const auto dir = test::scratch_dir("cli_tty_progress");
  const std::string mesh = kCli + " mesh torus --method mc --grid 24 -o " + (dir / "t.ply").string();
  // Not a terminal (stderr is a file): no progress line.
  const auto plain = test::run_command(mesh, dir);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_TRUE(plain.err.empty()) << plain.err;
  // A terminal (util-linux `script` runs the tool on a pseudo-terminal): progress, unless --quiet.
  if (test::run_command("command -v script", dir).exit_code != 0)
    GTEST_SKIP() << "no 'script' to fake a terminal";
  const auto tty = test::run_command("script -qec '" + mesh + "' /dev/null", dir);
  ASSERT_EQ(tty.exit_code, 0) << tty.out << tty.err;
  EXPECT_NE(tty.out.find("isopatch: mc "), std::string::npos) << tty.out;
  EXPECT_EQ(last_progress(tty.out, "slabs").first, last_progress(tty.out, "slabs").second) << tty.out;
  const auto quiet = test::run_command("script -qec '" + mesh + " --quiet' /dev/null", dir);
  ASSERT_EQ(quiet.exit_code, 0) << quiet.out << quiet.err;
  EXPECT_EQ(quiet.out.find("slabs"), std::string::npos) << quiet.out;
}

TEST(Cli, ProgressLineEndsBeforeAnErrorMessage) {
  // The torus's lowest slabs are empty, so progress is drawn before the vertex budget runs out.
  const auto dir = test::scratch_dir("cli_progress_error");
  const auto r = test::run_command(
      kCli + " mesh torus --method mc --grid 48 --max-vertices 10 --progress -o " + (dir / "t.ply").string(),
      dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::Limit)) << r.err;
  ASSERT_EQ(count_lines(r.err), 2) << r.err;  // the progress line, then the error on a line of its own
  const std::string second = r.err.substr(r.err.find('\n') + 1);
  EXPECT_EQ(second.rfind("isopatch: the mesh would exceed the vertex budget of 10 (--max-vertices)", 0), 0u)
      << r.err;
  EXPECT_GT(last_progress(r.err, "slabs").first, 0) << r.err;
}

TEST(Cli, WarnsWhereCellsAtTheDepthLimitStayInDoubt) {
  // Two spheres 0.01 apart (radii 0.995 and 1.005) cannot be told apart by cells of 0.19: the mesh is
  // written, with a warning that names the depth limit; a surface the cells resolve gives no warning.
  const auto dir = test::scratch_dir("cli_doubtful");
  const std::string out = " -o " + (dir / "m.ply").string();
  const auto thin =
      test::run_command(kCli + " mesh \"(x^2+y^2+z^2-1)^2-0.0001\" --box -1.5,-1.5,-1.5,1.5,1.5,1.5" +
                            " --max-depth 4 --edge-length 0.3 -q" + out,
                        dir);
  ASSERT_EQ(thin.exit_code, 0) << thin.err;
  EXPECT_EQ(count_lines(thin.err), 1) << thin.err;
  EXPECT_EQ(thin.err.rfind("warning: ", 0), 0u) << thin.err;
  EXPECT_NE(thin.err.find("at the depth limit 4 (side "), std::string::npos) << thin.err;
  const auto torus = test::run_command(kCli + " mesh torus --edge-length 0.1 -q" + out, dir);
  ASSERT_EQ(torus.exit_code, 0) << torus.err;
  EXPECT_TRUE(torus.err.empty()) << torus.err;
}

TEST(Cli, WarnsAboutAnglesUnderTenDegreesLeftByTheCleanUp) {
  // A disc-like ellipsoid 1 : 1 : 0.05 has a rim of radius 0.0025, twenty times narrower than the
  // edges. By default the sizes follow the rim (local_sizes_cli_test.cpp); with one size the clean-up
  // cannot remove every sliver there, and says so. Marching cubes alone makes slivers by design and is
  // not warned about.
  const auto dir = test::scratch_dir("cli_slivers");
  const std::string out = " -o " + (dir / "m.ply").string();
  const std::string disc = kCli + " mesh \"x^2+y^2+400*z^2-1\" --box -1.15,-1.15,-0.07,1.15,1.15,0.07 -q";
  const auto projected = test::run_command(disc + " --edge-length 0.04937 --uniform" + out, dir);
  ASSERT_EQ(projected.exit_code, 0) << projected.err;
  EXPECT_EQ(count_lines(projected.err), 1) << projected.err;
  EXPECT_NE(projected.err.find("have an angle under 10 degrees"), std::string::npos) << projected.err;
  const auto mc = test::run_command(disc + " --method mc --grid 40" + out, dir);
  ASSERT_EQ(mc.exit_code, 0) << mc.err;
  EXPECT_TRUE(mc.err.empty()) << mc.err;
}

}  // namespace
}  // namespace isopatch
