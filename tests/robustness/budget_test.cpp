// Evaluation and time budgets: a run stops with LimitError (exit code 9 from the tool) as soon as it has
// used its budget, whatever the method, instead of running on.
#include <isopatch/catalogue.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

#include "api/time_share.hpp"

#ifdef ISOPATCH_CLI
#include "run_command.hpp"
#endif

namespace isopatch {
namespace {

/// The budget (LimitError::setting) that stopped the run, and its message.
std::string limit_message(const Surface& s, const Settings& settings) {
  try {
    mesh_surface(s, settings);
  } catch (const LimitError& e) {
    return e.setting() + ": " + e.what();
  }
  return "no LimitError";
}

TEST(Budgets, EvaluationBudgetStopsEveryMethod) {
  const SurfacePtr torus = catalogue_surface("torus");
  for (const Method method : {Method::Projection, Method::MarchingCubes}) {
    Settings settings;
    settings.method = method;
    settings.max_evaluations = 2000;
    const std::string message = limit_message(*torus, settings);
    EXPECT_EQ(message.rfind("max_evaluations: the evaluation budget of 2000", 0), 0u) << method_name(method);
    // The library speaks of its settings, never of the command line's flags.
    EXPECT_EQ(message.find("--"), std::string::npos) << message;
    // A budget the run fits in changes nothing.
    settings.max_evaluations = 50'000'000;
    MeshStats stats;
    EXPECT_GT(mesh_surface(*torus, settings, &stats).vertex_count(), 1000u);
  }
}

TEST(Budgets, TimeLimitStopsALongRunEarly) {
  const SurfacePtr tanglecube = catalogue_surface("tanglecube");
  Settings settings;
  settings.edge_length = 0.004;  // millions of vertices: many seconds without a limit
  settings.max_depth = 12;
  settings.time_limit = 0.05;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(limit_message(*tanglecube, settings).rfind("time_limit: the time limit of", 0), 0u);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 5.0);
}

TEST(Budgets, TheStagesOfACsgRunShareOneTimeLimit) {
  // A gyroid minus a ball whose creases leave the box: the crease analysis, the shape cut open by the box
  // and the smooth mesher each take their time; the limit holds for the whole run, and the error names
  // the limit that was set, not what a late stage was left of it.
  const SurfacePtr f =
      expression_surface("max(sin(9*x)*cos(9*y)+sin(9*y)*cos(9*z)+sin(9*z)*cos(9*x),1-x^2-y^2-z^2)",
                         Box{Vec3::Constant(-1.2), Vec3::Constant(1.2)});
  Settings settings;
  settings.edge_length = 0.01;
  settings.time_limit = 0.3;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(limit_message(*f, settings), "time_limit: the time limit of 0.300000 s is exceeded");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 10.0);
}

TEST(Budgets, EachStageGetsWhatTheEarlierOnesLeft) {
  Settings settings;
  settings.time_limit = 0.2;
  const TimeShare share(settings);
  const Settings first = share.next();
  EXPECT_GT(first.time_limit, 0.1);
  EXPECT_LE(first.time_limit, 0.2);
  std::this_thread::sleep_for(std::chrono::milliseconds(120));
  EXPECT_LT(share.next().time_limit, 0.1);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  try {
    (void)share.next();
    ADD_FAILURE() << "no LimitError once the limit is spent";
  } catch (const LimitError& e) {
    EXPECT_EQ(e.setting(), "time_limit");
    EXPECT_STREQ(e.what(), "the time limit of 0.200000 s is exceeded");
  }
  // Without a limit every stage has none.
  const Settings none;
  EXPECT_EQ(TimeShare(none).next().time_limit, 0.0);
}

TEST(Budgets, RejectsANegativeTimeLimit) {
  Settings settings;
  settings.time_limit = -1.0;
  EXPECT_THROW(mesh_surface(*catalogue_surface("sphere"), settings), InputError);
}

#ifdef ISOPATCH_CLI
TEST(Budgets, ToolExitsWithTheLimitCode) {
  const auto dir = test::scratch_dir("budgets");
  const auto r = test::run_command(
      std::string(ISOPATCH_CLI) + " mesh torus -o " + (dir / "t.ply").string() + " --max-evaluations 500",
      dir);
  EXPECT_EQ(r.exit_code, 9) << r.err;
  EXPECT_NE(r.err.find("evaluation budget"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(--max-evaluations)"), std::string::npos) << r.err;  // the flag at fault
  EXPECT_FALSE(std::filesystem::exists(dir / "t.ply"));
}
#endif

}  // namespace
}  // namespace isopatch
