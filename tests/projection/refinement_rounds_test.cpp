// The one refinement loop (refinement_rounds.hpp): passes until every patch is accepted, the last
// allowed pass closing what is still rejected, and, when nothing can be refined, the rejected patches of
// the pass just made closed without meshing everything again.
#include "projection/refinement_rounds.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace isopatch {
namespace {

/// A producer of patches: patch p accepted once it has been refined `needs[p]` times, at most
/// `finest` times.
struct FakeProducer {
  FakeProducer(std::vector<int> refinements_needed, int finest_level = 100)
      : needs(std::move(refinements_needed)), finest(finest_level), level(needs.size(), 0) {}

  std::vector<int> needs;
  int finest;
  std::vector<int> level;
  std::vector<bool> closing_passes;  // close_rejected of each pass
  std::vector<std::size_t> closed;   // patches closed by fans
  int cancels = 0;

  std::vector<std::size_t> pass(bool close_rejected) {
    closing_passes.push_back(close_rejected);
    std::vector<std::size_t> rejected;
    for (std::size_t p = 0; p < needs.size(); ++p)
      if (level[p] < needs[p]) rejected.push_back(p);
    if (!close_rejected) return rejected;
    closed.insert(closed.end(), rejected.begin(), rejected.end());
    return {};
  }
  bool refine(const std::vector<std::size_t>& rejected) {
    bool refined = false;
    for (const std::size_t p : rejected)
      if (level[p] < finest) ++level[p], refined = true;
    return refined;
  }
  std::size_t run(int max_rounds) {
    return refine_until_accepted(
        max_rounds, [&](bool close) { return pass(close); },
        [&](const std::vector<std::size_t>& r) { return refine(r); },
        [&](const std::vector<std::size_t>& r) { closed.insert(closed.end(), r.begin(), r.end()); },
        [&] { ++cancels; });
  }
};

TEST(RefinementRounds, RefinesUntilEveryPatchIsAccepted) {
  FakeProducer producer({0, 2, 1});
  EXPECT_EQ(producer.run(5), 2u);
  EXPECT_EQ(producer.closing_passes, (std::vector<bool>{false, false, false}));
  EXPECT_TRUE(producer.closed.empty());
  EXPECT_EQ(producer.cancels, 3);  // before every pass
}

TEST(RefinementRounds, TheLastAllowedPassClosesWhatIsStillRejected) {
  FakeProducer producer({0, 5, 1});
  EXPECT_EQ(producer.run(2), 2u);
  EXPECT_EQ(producer.closing_passes, (std::vector<bool>{false, false, true}));
  EXPECT_EQ(producer.closed, (std::vector<std::size_t>{1}));
}

TEST(RefinementRounds, NothingLeftToRefineClosesThePassJustMadeWithoutAnotherPass) {
  FakeProducer producer({3, 0, 9}, 1);
  EXPECT_EQ(producer.run(5), 1u);
  // One refining pass, one that finds patches 0 and 2 at their finest level: no third pass.
  EXPECT_EQ(producer.closing_passes, (std::vector<bool>{false, false}));
  EXPECT_EQ(producer.closed, (std::vector<std::size_t>{0, 2}));
}

}  // namespace
}  // namespace isopatch
