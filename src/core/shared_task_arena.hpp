#pragma once
/// \file shared_task_arena.hpp
/// One TBB task arena per worker count for the whole process, made on first use and kept.
///
/// oneTBB 2021.8 (Debian 12) does not give back all the memory of an arena that many threads create
/// and destroy around them: an arena made per call from eight threads grew a process by 1.5-8 MB a
/// second (the viewer's server grew from 64 to 197 MB in three minutes of requests), while one kept
/// arena held it flat. Several threads may run in one arena at once; TBB shares its workers among them.

#include <tbb/task_arena.h>

namespace isopatch {

/// The process's arena of `threads` workers (threads >= 1), made the first time a count is asked for
/// and kept until exit. Thread-safe. Past kMaxSharedArenas distinct counts, returns nullptr: the
/// caller then makes an arena of its own for that call (see run_in_task_arena()).
tbb::task_arena* shared_task_arena(int threads);

/// How many distinct worker counts keep an arena.
inline constexpr int kMaxSharedArenas = 16;

}  // namespace isopatch
