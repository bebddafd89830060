#pragma once
/// \file patch_validity.hpp
/// A cheap check that each I-patch of a composite is one sheet inside its region and does not bulge
/// out through its planar ribbons (the defects of default weights with strongly unequal setbacks, or
/// of a reference point badly placed): lines along the direction most central to the patch's corner
/// directions are marched through the part of its region near its boundary, counting the sign changes of its
/// function. The lines run along the direction most central to the corner directions (central_direction).

#include "ipatch/composite.hpp"

#include <isopatch/geometry.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace isopatch {

struct PatchFinding {
  std::size_t patch = 0;
  std::string message;  ///< one line: "<patch name>: ..."
};

struct ValidityOptions {
  int lines_per_axis = 20;        ///< lines_per_axis^2 lines per patch
  int steps_per_line = 240;       ///< samples along each line
  double bulge_tolerance = 1e-3;  ///< relative to the patch's size
};

/// The unit direction d that maximizes min_k directions[k].d (approximately; it starts from their
/// normalized sum), or NaN when they sum to zero. The lines of the check run along it: a patch whose
/// normals all lean toward d meets each such line at most once.
Vec3 central_direction(const std::vector<Vec3>& directions);

/// What the lines found on one patch.
struct PatchShape {
  int lines = 0;             ///< lines that were marched
  int multi_root_lines = 0;  ///< lines that met the patch more than once inside its region
  int most_roots = 0;
  double bulge = 0.0;  ///< the largest value of a planar ribbon at a root (> 0: above a face plane)
  double size = 0.0;   ///< the diagonal of the patch's boundary, the scale of the tolerances
};

/// Marches the lines through one I-patch (\pre its surface is an IPatchSurface; else all zero).
PatchShape measure_patch(const Composite& composite, std::size_t patch, const ValidityOptions& options = {});

/// Per patch with an I-patch function (others are planes and cylinders, single sheets by construction):
/// a finding when some line meets the patch more than once inside its region, or when the patch rises
/// above one of its planar ribbons (a face plane of a setback vertex blend) by more than
/// bulge_tolerance times its size. Deterministic; about lines * steps * n evaluations per patch.
std::vector<PatchFinding> check_patch_validity(const Composite& composite,
                                               const ValidityOptions& options = {});

}  // namespace isopatch
