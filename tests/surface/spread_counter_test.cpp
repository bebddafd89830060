// The Sampler's evaluation counts: exact when many threads count at once (SpreadCounter), and the
// same totals for one or several threads.
#include <gtest/gtest.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <isopatch/resolve_surface.hpp>

#include "surface/sampler.hpp"

namespace isopatch {
namespace {

TEST(SpreadCounter, CountsEveryIncrementFromManyThreads) {
  for (int threads : {1, 2, 4, 80}) {  // 80: more workers than slots, so slots are shared
    SpreadCounter counter;
    tbb::task_arena arena(threads);
    arena.execute([&] { tbb::parallel_for(0, 200000, [&](int) { counter.add(); }); });
    EXPECT_EQ(counter.total(), 200000u) << threads << " threads";
  }
}

TEST(SpreadCounter, SamplerCountsTheSameForAnyThreadCount) {
  const SurfacePtr torus = catalogue_surface("torus");
  std::uint64_t values[2], gradients[2];
  for (int k = 0; k < 2; ++k) {
    const Sampler f(*torus);
    tbb::task_arena arena(k == 0 ? 1 : 4);
    arena.execute([&] {
      tbb::parallel_for(0, 5000, [&](int i) {
        const Vec3 p(0.001 * i, 0.5, 0.25);
        f.value(p);
        if (i % 3 == 0) f.value_gradient(p);
      });
    });
    values[k] = f.value_count();
    gradients[k] = f.gradient_count();
  }
  EXPECT_EQ(values[0], 5000u);
  EXPECT_EQ(gradients[0], 1667u);
  EXPECT_EQ(values[1], values[0]);
  EXPECT_EQ(gradients[1], gradients[0]);
}

}  // namespace
}  // namespace isopatch
