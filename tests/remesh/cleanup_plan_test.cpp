// The clean-up's plan (cleanup_plan.hpp): the whole run takes its rounds of split, collapse, flip and
// relax, then the repair rounds and the optional stages its settings ask for; the preview's local run
// (the preview preset) takes no round and never splits. The plan is what runs (the run's times are booked
// under its stage names), and a caller's pass inserted into it runs where it was put.
#include <isopatch/isopatch.hpp>
#include <isopatch/remesh.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "remesh/cleanup_plan.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace {

using namespace cleanup_stages;
using cleanup::CleanupPass;
using cleanup::CleanupPlan;
using cleanup::CleanupStep;
using cleanup::default_cleanup_plan;
using cleanup::RemeshRun;
using cleanup::stage_names;
using Names = std::vector<std::string_view>;

bool takes(const CleanupPlan& p, std::string_view stage) {
  for (const auto* part : {&p.setup, &p.round, &p.finish}) {
    const Names names = stage_names(*part);
    if (std::find(names.begin(), names.end(), stage) != names.end()) return true;
  }
  return false;
}

TEST(CleanupPlan, WholeRunRoundsThenFinish) {
  RemeshSettings settings;
  settings.cleanup.valence_search = 4;
  settings.cleanup.curvature_sweeps = 2;
  const CleanupPlan p = default_cleanup_plan(settings);
  EXPECT_EQ(stage_names(p.setup), (Names{kSizes}));
  EXPECT_EQ(stage_names(p.round), (Names{kSplit, kSizes, kCollapse, kSizes, kFlip, kRelax, kSizes}));
  EXPECT_EQ(stage_names(p.finish),
            (Names{kRepair, kSizes, kFlip, kRelax, kValenceSearch, kRelax, kCurvature, kRepair}));
  EXPECT_EQ(p.finish.front().repeats, 3);  // the repairs until one changes nothing
  settings.cleanup.valence_search = 0;
  settings.cleanup.curvature_sweeps = 0;
  settings.sizes.max_error = 1e-3;
  EXPECT_EQ(stage_names(default_cleanup_plan(settings).finish),
            (Names{kRepair, kSizes, kFlip, kRelax, kRelax, kRepair, kErrorBound}));
}

TEST(CleanupPlan, LocalRunHasNoRoundsAndNoSplits) {
  RemeshSettings settings;
  settings.cleanup.quality = Quality::Preview;
  settings.cleanup.valence_search = 4;
  const CleanupPlan p = default_cleanup_plan(settings);
  EXPECT_TRUE(p.round.empty());
  EXPECT_FALSE(takes(p, kSplit));
  EXPECT_FALSE(takes(p, kCurvature));
  EXPECT_EQ(stage_names(p.setup), (Names{kSizes}));
  EXPECT_EQ(stage_names(p.finish), (Names{kCollapse, kRepair, kFlip, kSizes, kRelax, kRepair, kFlip, kRelax,
                                          kRepair, kValenceSearch, kRelax, kRepair}));
  EXPECT_TRUE(static_cast<bool>(p.finish.back().when));  // only below the valence-six margin
  settings.cleanup.valence_search = 0;
  EXPECT_FALSE(takes(default_cleanup_plan(settings), kValenceSearch));
}

/// A sphere meshed by the projection alone, and clean-up settings for it.
struct Input {
  SurfacePtr surface = test::sphere();
  Mesh mesh;
  RemeshSettings settings;
  Input() {
    Settings s;
    s.edge_length = 0.15;
    s.remesh_iterations = 0;
    mesh = mesh_surface(*surface, s);
    settings.sizes.largest = 0.15;
    settings.cleanup.remesh_iterations = 3;
  }
};

std::set<std::string> timed_stages(const RemeshStats& stats) {
  std::set<std::string> out;
  for (const auto& entry : stats.times.seconds) out.insert(entry.first);
  return out;
}

std::set<std::string> planned_stages(const CleanupPlan& p) {
  std::set<std::string> out;
  for (const auto* part : {&p.setup, &p.round, &p.finish})
    for (std::string_view name : stage_names(*part)) out.emplace(name);
  return out;
}

TEST(CleanupPlan, TheDefaultPlanIsWhatRuns) {
  for (const bool local : {false, true}) {
    Input in;
    in.settings.cleanup.quality = local ? Quality::Preview : Quality::Default;
    in.settings.sizes.max_error = local ? std::nullopt : std::optional<double>(2e-3);
    in.settings.sizes.smallest = 0.01;
    const RemeshStats stats = remesh_on_surface(in.mesh, *in.surface, in.settings);
    const std::set<std::string> planned = planned_stages(default_cleanup_plan(in.settings));
    std::set<std::string> timed = timed_stages(stats);
    // The local run's valence search runs only below its valence-six margin (here, either way).
    if (local) timed.insert(kValenceSearch);
    EXPECT_EQ(timed, planned) << (local ? "local" : "whole");
  }
}

TEST(CleanupPlan, ACallersPassRunsWhereItIsPut) {
  Input in;
  CleanupPlan plan = default_cleanup_plan(in.settings);
  // After every round's splits: the count of live vertices the splits left, once per round.
  std::vector<std::size_t> after_split;
  plan.round.insert(plan.round.begin() + 1, cleanup::single_pass("my_census", [&](RemeshRun& run) {
                      after_split.push_back(run.mesh.vertex_slots());
                      return std::size_t{0};
                    }));
  // A repeated step whose first pass edits twice: the step ends on the third repeat's first pass.
  int first = 0, second = 0;
  plan.finish.push_back(
      CleanupStep{{{"my_counted", [&](RemeshRun&) { return std::size_t(first++ < 2); }},
                   {"my_follower", [&](RemeshRun&) { return static_cast<std::size_t>(++second); }}},
                  5,
                  {},
                  false});
  // A step whose condition fails never runs.
  bool skipped_ran = false;
  plan.finish.push_back(
      CleanupStep{{{"my_skipped", [&](RemeshRun&) { return std::size_t(skipped_ran = true); }}},
                  1,
                  [](const RemeshRun&) { return false; },
                  false});
  const RemeshStats stats = cleanup::remesh_with_plan(in.mesh, *in.surface, in.settings, plan);
  EXPECT_EQ(after_split.size(), 3u);
  EXPECT_EQ(first, 3);
  EXPECT_EQ(second, 2);
  EXPECT_FALSE(skipped_ran);
  const std::set<std::string> timed = timed_stages(stats);
  EXPECT_TRUE(timed.count("my_census") && timed.count("my_counted") && timed.count("my_follower"));
  EXPECT_FALSE(timed.count("my_skipped"));
  // The default passes still did their work around the caller's.
  EXPECT_TRUE(analyze_topology(in.mesh).watertight());
  for (const Vec3& p : in.mesh.positions) EXPECT_NEAR(p.norm(), 1.0, 1e-9);
}

}  // namespace
}  // namespace isopatch
