// End-to-end tests of what issue 24 added to the tool: .glb output, analyze/render of a mesh against a
// formula without --box, and `isopatch view` refusing bad input before it serves anything.
#include <gtest/gtest.h>

#include <string>

#include "run_command.hpp"

namespace isopatch {
namespace {

const std::string kViewerCli = ISOPATCH_CLI;  // (test_cli is a unity build: a name of its own)

TEST(ViewerCli, MeshWritesGlbWithTheChosenColours) {
  const auto dir = test::scratch_dir("cli_glb");
  const auto glb = (dir / "t.glb").string();
  auto r = test::run_command(kViewerCli + " mesh sphere --edge-length 0.2 -q -o " + glb, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string bytes = test::read_text(glb);
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_NE(bytes.find("\"COLOR_0\""), std::string::npos) << "mean curvature by default, without --fields";
  EXPECT_EQ(bytes.find("_MEAN_CURVATURE"), std::string::npos) << "the fields only with --fields";

  r = test::run_command(kViewerCli + " mesh sphere --edge-length 0.2 -q --fields --colour none -o " + glb,
                        dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  bytes = test::read_text(glb);
  EXPECT_EQ(bytes.find("\"COLOR_0\""), std::string::npos);
  EXPECT_NE(bytes.find("\"_MEAN_CURVATURE\""), std::string::npos);
  EXPECT_NE(bytes.find("\"_DISTANCE\""), std::string::npos);

  r = test::run_command(kViewerCli + " mesh sphere --colour pink -o " + glb, dir);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("unknown colour field 'pink'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(--colour)"), std::string::npos) << r.err;
}

TEST(ViewerCli, AnalyzeAndRenderUseTheMeshBoundsForAFormula) {
  const auto dir = test::scratch_dir("cli_mesh_bounds");
  const auto ply = (dir / "s.ply").string();
  auto r = test::run_command(kViewerCli + " mesh sphere --edge-length 0.2 -q -o " + ply, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string formula = "\"x^2 + y^2 + z^2 - 1\"";
  r = test::run_command(kViewerCli + " analyze " + ply + " --surface " + formula + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"accuracy\""), std::string::npos);
  r = test::run_command(kViewerCli + " render " + ply + " -q -o " + (dir / "s.png").string() +
                            " --show mean-curvature --surface " + formula,
                        dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // An explicit box still wins, and is still checked.
  r = test::run_command(kViewerCli + " analyze " + ply + " --surface " + formula + " --box 1,1,1,0,0,0", dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
}

TEST(ViewerCli, ViewRefusesBadInputBeforeServing) {
  const auto dir = test::scratch_dir("cli_view_errors");
  auto r = test::run_command(kViewerCli + " view \"x^2 + * y\" --box -1,-1,-1,1,1,1", dir);
  EXPECT_EQ(r.exit_code, 5) << r.err;
  EXPECT_EQ(r.out, "") << "no URL for a surface that does not parse";
  EXPECT_NE(r.err.find("column 7"), std::string::npos) << r.err;
  r = test::run_command(kViewerCli + " view \"x^2 + y^2 + z^2 - 1\"", dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("(--box)"), std::string::npos) << r.err;
  r = test::run_command(kViewerCli + " view torus --port 70000", dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  r = test::run_command(kViewerCli + " view torus --web-root " + (dir / "nothing").string(), dir);
  EXPECT_EQ(r.exit_code, 6) << r.err;
  EXPECT_NE(r.err.find("install-deps"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace isopatch
