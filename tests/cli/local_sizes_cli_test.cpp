// Sizes refined where f = 0 turns within an edge, as the tool reports them (issue 35): the warning line
// and the local_sizes section of --stats-json, and --uniform turning them off.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "run_command.hpp"

namespace isopatch {
namespace {

const std::string kLocalSizesCli = ISOPATCH_CLI;

// An ellipsoid with semi-axes 4, 1, 0.2: its rim turns with radius 0.01, a thirteenth of the default edge.
TEST(LocalSizesCli, ThinRimRefinedWithAWarningUnlessUniform) {
  const auto dir = test::scratch_dir("cli_thin_rim");
  const auto out = dir / "rim.ply";
  const std::string mesh =
      kLocalSizesCli + " mesh x^2/16+y^2+z^2/0.04-1 --box -4.2,-4.2,-4.2,4.2,4.2,4.2 -q -o " + out.string();
  auto r = test::run_command(mesh + " --stats-json " + (dir / "s.json").string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("points where f = 0 turns within an edge"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("vertices added (--uniform keeps one size)"), std::string::npos) << r.err;
  const auto stats = nlohmann::json::parse(test::read_text(dir / "s.json"));
  ASSERT_TRUE(stats.contains("local_sizes"));
  const auto& sizes = stats["local_sizes"];
  EXPECT_GT(sizes["curvature_sources"].get<double>(), 0.0);
  EXPECT_EQ(sizes["sources"].get<double>(), 0.0);
  EXPECT_GT(sizes["added_vertices"].get<double>(), 0.0);
  EXPECT_LT(sizes["smallest_size"].get<double>(), 0.01);           // under the rim's radius
  EXPECT_LT(sizes["extent_hi_z"].get<double>(), 0.2);              // along the rim, within the sheet's height
  EXPECT_GT(stats["projection"]["max_depth"].get<double>(), 8.0);  // deeper than --max-depth: the sizes
  r = test::run_command(mesh + " --uniform", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("turns within an edge"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace isopatch
