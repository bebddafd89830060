// What the parallel and repeated adaptive builds share: the sample cache's overlays (read the base,
// evaluate the rest, merge back) and the memo that carries samples and crossings from one build to the
// next. Both must leave the partition exactly as a fresh, one-task build makes it.
#include "partition/adaptive_partition.hpp"
#include "partition/lattice.hpp"
#include "partition/partition.hpp"
#include "partition/sample_cache.hpp"
#include "surface/sampler.hpp"
#include "test_surfaces.hpp"

#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace isopatch {
namespace {

void expect_same_partition(const Partition& a, const Partition& b) {
  ASSERT_EQ(a.leaves.size(), b.leaves.size());
  for (std::size_t i = 0; i < a.leaves.size(); ++i) {
    const Leaf &x = a.leaves[i], &y = b.leaves[i];
    EXPECT_EQ(x.depth, y.depth);
    EXPECT_EQ(x.coords, y.coords);
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_EQ(x.reason, y.reason);
    ASSERT_EQ(x.loops.size(), y.loops.size());
    for (std::size_t l = 0; l < x.loops.size(); ++l) EXPECT_EQ(x.loops[l].corners, y.loops[l].corners);
  }
  ASSERT_EQ(a.crossings.size(), b.crossings.size());
  for (std::size_t c = 0; c < a.crossings.size(); ++c) {
    EXPECT_TRUE(a.crossings[c].segment == b.crossings[c].segment);
    EXPECT_EQ(a.crossings[c].position, b.crossings[c].position);  // bit for bit
    EXPECT_EQ(a.crossings[c].gradient, b.crossings[c].gradient);
  }
}

TEST(SampleCacheOverlay, ReadsTheBaseEvaluatesTheRestAndMergesBack) {
  const SurfacePtr surface = test::torus();
  const Lattice lattice = make_lattice(surface->box(), 6);
  const Sampler sampler(*surface);
  SampleCache base(sampler, lattice, 4);
  const LatticePoint known{10, 20, 30}, fresh{70, 40, 12};
  const SegmentKey segment{{8, 8, 8}, 0, 4};
  const double known_value = base.value(known);
  const std::uint64_t before = sampler.value_count();

  SampleCache overlay = SampleCache::overlay(base);
  EXPECT_EQ(overlay.value(known), known_value);
  EXPECT_EQ(sampler.value_count(), before) << "a value the base holds is read, not evaluated";
  const double fresh_value = overlay.value(fresh);
  EXPECT_EQ(fresh_value, surface->value(lattice.half_point(fresh)));
  EXPECT_EQ(sampler.value_count(), before + 1);
  const Vec3 gradient = overlay.gradient(known);  // the base has no gradient there: the overlay adds it
  const std::vector<double> samples(overlay.segment_samples(segment).begin(),
                                    overlay.segment_samples(segment).end());
  ASSERT_EQ(samples.size(), 4u);
  for (std::size_t k = 0; k < samples.size(); ++k) {  // the batch gives the single-point values
    const double t = static_cast<double>(k + 1) / 5.0;
    EXPECT_EQ(samples[k],
              surface->value((1.0 - t) * lattice.point(segment.start) + t * lattice.point(segment.end())));
  }
  overlay.merge_into(base);
  const std::uint64_t merged = sampler.value_count();
  EXPECT_EQ(base.value(fresh), fresh_value);
  EXPECT_EQ(base.gradient(known), gradient);
  const auto again = base.segment_samples(segment);
  EXPECT_EQ(std::vector<double>(again.begin(), again.end()), samples);
  EXPECT_EQ(sampler.value_count(), merged) << "the merged values are not evaluated again";
  EXPECT_EQ(base.segment_sample_evaluations(), 4u);
}

TEST(AdaptiveBuildMemo, RebuildsMakeTheSamePartitionWithFewerEvaluations) {
  for (const auto& [name, surface] : {std::pair{std::string("genus2"), test::genus2()},
                                      std::pair{std::string("tanglecube"), test::tanglecube()}}) {
    SCOPED_TRACE(name);
    PartitionSettings settings;
    settings.surface_depth = 3;
    settings.max_depth = 6;
    settings.adaptive = true;
    std::unique_ptr<AdaptiveBuildMemo> memo;
    const Partition first = build_partition(*surface, surface->box(), settings, memo);
    expect_same_partition(first, build_partition(*surface, surface->box(), settings));
    // A rebuild with forced splits, then one a level finer (as the refining mesher asks for them).
    for (std::size_t i = 0; i < first.leaves.size(); i += 4)
      settings.force_split.push_back(CellKey{first.leaves[i].depth, first.leaves[i].coords});
    const Partition fresh = build_partition(*surface, surface->box(), settings);
    const Partition reused = build_partition(*surface, surface->box(), settings, memo);
    expect_same_partition(fresh, reused);
    EXPECT_LT(reused.stats.value_evaluations, fresh.stats.value_evaluations);  // only the new cells' samples
    settings.force_split.clear();
    ++settings.surface_depth;
    expect_same_partition(build_partition(*surface, surface->box(), settings),
                          build_partition(*surface, surface->box(), settings, memo));
  }
  // A memo belongs to one surface, box and lattice.
  PartitionSettings settings;
  settings.surface_depth = 2;
  settings.max_depth = 5;
  settings.adaptive = true;
  const SurfacePtr sphere = test::sphere(), torus = test::torus();
  std::unique_ptr<AdaptiveBuildMemo> memo;
  build_partition(*sphere, sphere->box(), settings, memo);
  EXPECT_THROW(build_partition(*torus, torus->box(), settings, memo), Error);
  settings.max_depth = 6;
  EXPECT_THROW(build_partition(*sphere, sphere->box(), settings, memo), Error);
}

}  // namespace
}  // namespace isopatch
