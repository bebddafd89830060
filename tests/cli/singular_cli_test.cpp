// The singular points of f = 0 as the tool reports them: the warning and the --stats-json section of
// `isopatch mesh`, and the element shape away from them in `isopatch analyze`.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "run_command.hpp"

namespace isopatch {
namespace {

const std::string kCli = ISOPATCH_CLI;
const std::string kWarning =
    "warning: 2 singular points of f = 0 (grad f = 0) in the box: (0, 0, -1), (0, 0, 1)\n";

nlohmann::json read_json(const std::filesystem::path& path) {
  return nlohmann::json::parse(test::read_text(path));  // throws (fails the test) if not JSON
}

TEST(SingularCli, HeartMeshWarnsOfItsTwoCuspsAndListsThemInTheStatistics) {
  const auto dir = test::scratch_dir("singular_cli_heart");
  const auto mesh = dir / "heart.ply", stats = dir / "heart.json";
  const auto r =
      test::run_command(kCli + " mesh heart -q -o " + mesh.string() + " --stats-json " + stats.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(kWarning), std::string::npos) << r.err;
  const nlohmann::json s = read_json(stats).at("singular_points");
  EXPECT_EQ(s.at("status"), "complete");
  EXPECT_TRUE(s.at("searched").get<bool>());
  EXPECT_TRUE(s.at("complete").get<bool>());
  EXPECT_EQ(s.at("points"), 2);
  EXPECT_EQ(s.at("curves"), 0);
  ASSERT_EQ(s.at("positions").size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const auto& p = s.at("positions")[static_cast<std::size_t>(k)];
    EXPECT_NEAR(p[0].get<double>(), 0.0, 1e-6);
    EXPECT_NEAR(p[1].get<double>(), 0.0, 1e-6);
    EXPECT_NEAR(p[2].get<double>(), k == 0 ? -1.0 : 1.0, 1e-6);
  }
  EXPECT_TRUE(s.at("curve_list").empty());
  // The equator, where only f is degenerate, is in the statistics but not in the warning.
  EXPECT_EQ(s.at("degenerate"), 1);
  EXPECT_GT(s.at("degenerate_list")[0].at("samples").get<int>(), 100);
  EXPECT_GT(s.at("boxes").get<int>(), 0);
  EXPECT_GE(s.at("seconds").get<double>(), 0.0);
}

TEST(SingularCli, SphereMeshSaysNothingAndItsStatisticsSayNone) {
  const auto dir = test::scratch_dir("singular_cli_sphere");
  const auto mesh = dir / "sphere.ply", stats = dir / "sphere.json";
  const auto r =
      test::run_command(kCli + " mesh sphere -o " + mesh.string() + " --stats-json " + stats.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("singular point"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("singular point"), std::string::npos) << r.out;
  const nlohmann::json s = read_json(stats).at("singular_points");
  EXPECT_TRUE(s.at("complete").get<bool>());
  EXPECT_EQ(s.at("points"), 0);
  EXPECT_EQ(s.at("curves"), 0);
  EXPECT_EQ(s.at("degenerate"), 0);
  EXPECT_TRUE(s.at("positions").empty());
}

TEST(SingularCli, CompositeSurfaceIsReportedAsNotSearched) {
  const auto dir = test::scratch_dir("singular_cli_composite");
  const auto mesh = dir / "cube.ply", stats = dir / "cube.json";
  const auto r =
      test::run_command(kCli + " mesh " + std::string(ISOPATCH_SOURCE_DIR) + "/examples/cube.ipatch -q -o " +
                            mesh.string() + " --stats-json " + stats.string(),
                        dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("singular point"), std::string::npos) << r.err;
  const nlohmann::json s = read_json(stats).at("singular_points");
  EXPECT_EQ(s.at("status"), "not searched");
  EXPECT_FALSE(s.at("searched").get<bool>());
  EXPECT_FALSE(s.at("complete").get<bool>());
  EXPECT_FALSE(s.at("reason").get<std::string>().empty());
}

TEST(SingularCli, AnalyzeGivesTheShapeAwayFromTheCusps) {
  const auto dir = test::scratch_dir("singular_cli_analyze");
  const auto mesh = dir / "heart.ply";
  ASSERT_EQ(test::run_command(kCli + " mesh heart -q -o " + mesh.string(), dir).exit_code, 0);
  const auto r = test::run_command(kCli + " analyze " + mesh.string() + " --surface heart --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("singular_points").at("points"), 2);
  const nlohmann::json& away = j.at("away_from_singular_points");
  const double edge = j.at("shape").at("edge_length").at("mean").get<double>();
  EXPECT_NEAR(away.at("radius").get<double>(), 2.0 * edge, 1e-12);
  const auto triangles = j.at("mesh").at("triangles").get<std::size_t>();
  const auto left_out = away.at("triangles_left_out").get<std::size_t>();
  EXPECT_GT(left_out, 0u);
  EXPECT_LT(left_out, triangles / 20);  // two balls of two edge lengths: a few dozen triangles
  EXPECT_EQ(away.at("triangles").get<std::size_t>() + left_out, triangles);
  // Away from the cusps the figures can only be as good or better than over the whole mesh.
  EXPECT_GE(away.at("min_angle_degrees").get<double>(),
            j.at("shape").at("min_angle_degrees").at("min").get<double>());
  EXPECT_LE(away.at("share_below_20_degrees").get<double>(),
            j.at("shape").at("share_below_20_degrees").get<double>() + 1e-12);
  const auto text = test::run_command(kCli + " analyze " + mesh.string() + " --surface heart", dir);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("singular   2 singular points of f = 0"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("away       outside balls of radius"), std::string::npos) << text.out;
}

TEST(SingularCli, AnalyzeOfTheSphereGivesNoFiguresAway) {
  const auto dir = test::scratch_dir("singular_cli_analyze_sphere");
  const auto mesh = dir / "sphere.ply";
  ASSERT_EQ(test::run_command(kCli + " mesh sphere -q -o " + mesh.string(), dir).exit_code, 0);
  const auto r = test::run_command(kCli + " analyze " + mesh.string() + " --surface sphere --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("singular_points").at("points"), 0);
  EXPECT_FALSE(j.contains("away_from_singular_points"));
  const auto text = test::run_command(kCli + " analyze " + mesh.string() + " --surface sphere", dir);
  EXPECT_EQ(text.out.find("\nsingular "), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("\naway "), std::string::npos) << text.out;
}

}  // namespace
}  // namespace isopatch
