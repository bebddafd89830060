// The process keeps one TBB task arena per worker count (core/shared_task_arena.hpp): the same count
// gives the same arena, of that many slots; callers on several threads at once share it and each gets
// the mesh it gets alone; past the limit of distinct counts a caller gets none (and makes its own).
#include <isopatch/catalogue.hpp>
#include <isopatch/isopatch.hpp>

#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "core/shared_task_arena.hpp"

namespace isopatch {
namespace {

TEST(SharedTaskArena, OneArenaPerWorkerCount) {
  tbb::task_arena* three = shared_task_arena(3);
  ASSERT_NE(three, nullptr);
  EXPECT_EQ(shared_task_arena(3), three);
  EXPECT_EQ(three->max_concurrency(), 3);
  tbb::task_arena* five = shared_task_arena(5);
  ASSERT_NE(five, nullptr);
  EXPECT_NE(five, three);
  EXPECT_EQ(five->max_concurrency(), 5);
}

TEST(SharedTaskArena, PastTheLimitOfCountsCallersGetNone) {
  std::vector<tbb::task_arena*> given;
  int none = 0;
  for (int threads = 101; threads <= 101 + kMaxSharedArenas; ++threads) {
    tbb::task_arena* arena = shared_task_arena(threads);
    if (arena == nullptr)
      ++none;
    else
      given.push_back(arena);
  }
  EXPECT_GE(none, 1);  // kMaxSharedArenas + 1 distinct counts
  EXPECT_LE(given.size(), static_cast<std::size_t>(kMaxSharedArenas));
  for (std::size_t i = 0; i < given.size(); ++i)
    EXPECT_EQ(shared_task_arena(given[i]->max_concurrency()), given[i]);  // kept
  // A count past the limit still meshes, in an arena of its own.
  Settings settings;
  settings.quality = Quality::Preview;
  settings.threads = 101 + kMaxSharedArenas + 1;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*catalogue_surface("sphere"), settings, &stats);
  EXPECT_GT(mesh.triangle_count(), 100u);
  EXPECT_EQ(stats.threads, settings.threads);
}

TEST(SharedTaskArena, CallersOnManyThreadsGetTheMeshOfOneAlone) {
  const SurfacePtr surface = catalogue_surface("torus");
  Settings settings;
  settings.edge_length = 0.15;
  settings.threads = 2;
  const Mesh alone = mesh_surface(*surface, settings);
  ASSERT_GT(alone.vertex_count(), 100u);
  constexpr int kCallers = 6;
  std::vector<Mesh> meshes(kCallers);
  std::vector<std::thread> callers;
  for (int i = 0; i < kCallers; ++i)
    callers.emplace_back([&, i] {
      Settings mine = settings;
      mine.threads = 1 + i % 3;  // three arenas, each shared by two callers
      meshes[i] = mesh_surface(*surface, mine);
    });
  for (std::thread& t : callers) t.join();
  for (int i = 0; i < kCallers; ++i) {
    SCOPED_TRACE("caller " + std::to_string(i));
    EXPECT_TRUE(meshes[i].positions == alone.positions);
    EXPECT_TRUE(meshes[i].triangles == alone.triangles);
  }
}

}  // namespace
}  // namespace isopatch
