// Small-angle repair of the surface-bound clean-up (one run's state: remesh_run.hpp).
#pragma once

#include <cstddef>

#include "remesh/remesh_run.hpp"

namespace isopatch::cleanup {

/// repair_small_angles, up to three passes: a repair can make a new small angle next to one it already
/// passed, so it repeats while it changes things.
void repair_until_settled(RemeshRun& run);

/// Removes triangles whose smallest angle is below kRepairAngle: flip the longest edge when that
/// raises the smallest angle of the pair, else collapse the shortest edge. Returns the changes made.
std::size_t repair_small_angles(RemeshRun& run);

}  // namespace isopatch::cleanup
