#pragma once
/// \file budget_checks.hpp
/// The projection mesher's checks of the caller's cancel flag and vertex budget (Settings).

#include <isopatch/error.hpp>
#include <isopatch/settings.hpp>

#include <atomic>
#include <cstddef>
#include <string>

namespace isopatch {

/// \throw LimitError("cancelled") when the caller's cancel flag is raised.
inline void check_cancel(const Settings& s) {
  if (s.cancel && s.cancel->load(std::memory_order_relaxed)) throw LimitError("cancelled");
}

/// \throw LimitError when `vertices` exceeds Settings::max_vertices (0: no limit).
inline void check_vertex_budget(const Settings& s, std::size_t vertices) {
  if (s.max_vertices > 0 && vertices > s.max_vertices)
    throw LimitError("the mesh would exceed --max-vertices " + std::to_string(s.max_vertices));
}

}  // namespace isopatch
