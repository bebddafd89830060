// shared_task_arena (shared_task_arena.hpp).
#include "core/shared_task_arena.hpp"

#include <map>
#include <memory>
#include <mutex>

namespace isopatch {

tbb::task_arena* shared_task_arena(int threads) {
  static std::mutex mutex;
  // Never destroyed: an arena must not outlive TBB's own state at exit, and the arenas are reachable
  // to the end (no leak to report).
  static auto* arenas = new std::map<int, std::unique_ptr<tbb::task_arena>>();
  const std::lock_guard lock(mutex);
  const auto found = arenas->find(threads);
  if (found != arenas->end()) return found->second.get();
  if (static_cast<int>(arenas->size()) >= kMaxSharedArenas) return nullptr;
  auto arena = std::make_unique<tbb::task_arena>(threads);
  arena->initialize();
  return arenas->emplace(threads, std::move(arena)).first->second.get();
}

}  // namespace isopatch
