// The clean-up's schedule (cleanup_schedule): the whole run takes its rounds of split, collapse, flip and
// relax, then the repair rounds and the optional stages its settings ask for; the preview's local run
// (local_only) takes no round and never splits.
#include <isopatch/remesh.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <string_view>
#include <vector>

#include "remesh/cleanup_stages.hpp"

namespace isopatch {
namespace {

using namespace cleanup_stages;
using Names = std::vector<std::string_view>;

bool takes(const CleanupSchedule& s, std::string_view stage) {
  for (const Names* part : {&s.setup, &s.round, &s.finish})
    if (std::find(part->begin(), part->end(), stage) != part->end()) return true;
  return false;
}

TEST(CleanupSchedule, WholeRunRoundsThenFinish) {
  RemeshSettings settings;
  settings.valence_search = 4;
  settings.curvature_sweeps = 2;
  const CleanupSchedule s = cleanup_schedule(settings);
  EXPECT_EQ(s.setup, (Names{kSizes}));
  EXPECT_EQ(s.round, (Names{kSplit, kSizes, kCollapse, kSizes, kFlip, kRelax, kSizes}));
  EXPECT_EQ(s.finish, (Names{kRepair, kSizes, kFlip, kRelax, kValenceSearch, kRelax, kCurvature, kRepair}));
  settings.valence_search = 0;
  settings.curvature_sweeps = 0;
  settings.sizes.max_error = 1e-3;
  EXPECT_EQ(cleanup_schedule(settings).finish,
            (Names{kRepair, kSizes, kFlip, kRelax, kRelax, kRepair, kErrorBound}));
}

TEST(CleanupSchedule, LocalRunHasNoRoundsAndNoSplits) {
  RemeshSettings settings;
  settings.local_only = true;
  settings.valence_search = 4;
  const CleanupSchedule s = cleanup_schedule(settings);
  EXPECT_TRUE(s.round.empty());
  EXPECT_FALSE(takes(s, kSplit));
  EXPECT_FALSE(takes(s, kCurvature));
  EXPECT_EQ(s.setup, (Names{kSizes}));
  EXPECT_EQ(s.finish, (Names{kCollapse, kRepair, kFlip, kSizes, kRelax, kRepair, kFlip, kRelax, kRepair,
                             kValenceSearch, kRelax, kRepair}));
  settings.valence_search = 0;
  EXPECT_FALSE(takes(cleanup_schedule(settings), kValenceSearch));
  EXPECT_NE(cleanup_schedule(settings).finish, s.finish);
}

}  // namespace
}  // namespace isopatch
