// Evaluation and time budgets: a run stops with LimitError (exit code 9 from the tool) as soon as it has
// used its budget, whatever the method, instead of running on.
#include <isopatch/catalogue.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <string>

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
