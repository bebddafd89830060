// Every second of `isopatch mesh` in its statistics: seconds.total from the process's start to the
// statistics, the stages around the mesher (start-up, input, searches, writing, the self-intersection
// check) and the mesher's own summing to it, and the summary's time line that total.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <string>

#include "run_command.hpp"

namespace isopatch {
namespace {

const std::string kClockCli = ISOPATCH_CLI;

TEST(RunClock, TheStagesAccountForTheWholeRunAndTheTimeLineIsItsTotal) {
  const auto dir = test::scratch_dir("cli_run_clock");
  const auto r =
      test::run_command(kClockCli + " mesh torus --edge-length 0.05 -o " + (dir / "t.ply").string() +
                            " --stats-json " + (dir / "s.json").string(),
                        dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto stats = nlohmann::json::parse(test::read_text(dir / "s.json"));
  const auto& seconds = stats.at("seconds");
  const double total = seconds.at("total").get<double>();
  double stages = 0.0;
  for (const auto& [name, value] : seconds.items())
    if (name != "total") stages += value.get<double>();
  for (const char* stage :
       {"startup", "input", "write", "self_intersections", "feature_search", "size_estimate"})
    EXPECT_TRUE(seconds.contains(stage)) << stage;
  EXPECT_GT(total, 0.0);
  EXPECT_GE(stages, 0.95 * total);
  EXPECT_LE(stages, 1.0001 * total + 1e-6);
  // The mesher's own seconds are part of the whole.
  EXPECT_LE(stats.at("mesh").at("seconds").get<double>(), total);
  const std::size_t line = r.out.find("\ntime ");
  ASSERT_NE(line, std::string::npos) << r.out;
  EXPECT_NEAR(std::strtod(r.out.c_str() + line + 6, nullptr), total, 1e-5);
}

}  // namespace
}  // namespace isopatch
