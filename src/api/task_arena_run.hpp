#pragma once
/// \file task_arena_run.hpp
/// The set-up every entry point shares (mesh_surface(), mesh_composite()): the run in a TBB task arena
/// of Settings::threads workers, so that every parallel loop of the pipeline uses that many. The arena
/// is the process's one for that count (core/shared_task_arena.hpp): one made per call leaked memory.

#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>

#include "core/shared_task_arena.hpp"

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <utility>

namespace isopatch {

/// Runs `run()` in an arena of settings.threads workers (every core when 0), recording the count in
/// stats->threads when stats is given; returns what run() returns. Throws what run() throws.
template <class Run>
auto run_in_task_arena(const Settings& settings, MeshStats* stats, Run&& run) {
  const int threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
  if (stats) stats->threads = threads;
  if (tbb::task_arena* shared = shared_task_arena(threads)) return shared->execute(std::forward<Run>(run));
  tbb::task_arena arena(threads);  // past kMaxSharedArenas distinct counts
  return arena.execute(std::forward<Run>(run));
}

}  // namespace isopatch
