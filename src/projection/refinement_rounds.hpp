#pragma once
/// \file refinement_rounds.hpp
/// The refinement loop of the projection mesher (Sipos & Salvi 2021, sec. 2.3: "reject and subdivide"),
/// one for every producer of patch jobs: mesh every patch; where the acceptance tests reject one,
/// refine around it (split its cell, or double the segments of its curves) and mesh again; the last of
/// `max_rounds` passes closes every rejected patch by a fan (fan_centre.hpp), and when nothing can be
/// refined further the rejected patches of the pass just made are closed.

#include <cstddef>
#include <vector>

namespace isopatch {

/// The producer's three steps.
///   pass(bool close_rejected) -> std::vector<std::size_t>: meshes every patch and returns the rejected
///     ones (ascending); with close_rejected, closes each by a fan instead and returns none.
///   refine(const std::vector<std::size_t>& rejected) -> bool: refines around them; false when nothing
///     could be refined (every rejected patch is at the finest level).
///   close(const std::vector<std::size_t>& rejected): closes those patches of the pass just made by
///     fans (called after refine returned false; a producer that can only close in a whole pass calls
///     pass(true)).
/// `check_cancel()` runs before every pass (it throws to stop).
/// \return the rounds of refinement made.
/// \throw whatever the steps throw.
template <class Pass, class Refine, class Close, class CheckCancel>
std::size_t refine_until_accepted(int max_rounds, Pass&& pass, Refine&& refine, Close&& close,
                                  CheckCancel&& check_cancel) {
  for (std::size_t round = 0;; ++round) {
    check_cancel();
    const bool last = round >= static_cast<std::size_t>(max_rounds < 0 ? 0 : max_rounds);
    const std::vector<std::size_t> rejected = pass(last);
    if (rejected.empty()) return round;
    if (!refine(rejected)) {
      close(rejected);
      return round;
    }
  }
}

}  // namespace isopatch
