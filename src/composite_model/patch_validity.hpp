#pragma once
/// \file patch_validity.hpp
/// A cheap check that each I-patch of a composite is one sheet inside its region and does not bulge
/// out through its planar ribbons (the defects of default weights with strongly unequal setbacks, or
/// of a reference point badly placed): lines along the direction most central to the patch's corner
/// directions are marched through the part of its region near its boundary, counting the sign changes of its
/// function. The lines run along the direction most central to the corner directions (central_direction).
/// Folds that hug a side, which such lines miss, are found by stepping just inside each side and
/// comparing the patch's normal with its ribbon's there (measure_boundary_bend).

#include "composite_model/composite.hpp"

#include <isopatch/geometry.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace isopatch {

struct PatchFinding {
  std::size_t patch = 0;
  std::string message;  ///< one line: "<patch name>: ..."
};

/// Degrees between a patch's normal and its ribbon's a small step beside a side (measure_boundary_bend):
/// beyond kFoldBend the patch folds there (the mesher cannot project onto it); the constructions'
/// searches for reference points stop at one that bends less than kGoodBend.
inline constexpr double kFoldBend = 80.0;
inline constexpr double kGoodBend = 45.0;

struct ValidityOptions {
  int lines_per_axis = 20;        ///< lines_per_axis^2 lines per patch
  int steps_per_line = 240;       ///< samples along each line
  double bulge_tolerance = 1e-3;  ///< relative to the patch's size
  double fold_angle = kFoldBend;  ///< degrees, see measure_boundary_bend
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

/// How the patch leaves its boundary: beside sample points of every side, at a small distance into the
/// region, the angle between the patch's normal and its ribbon's normal there.
struct BoundaryBend {
  double worst_angle = 0.0;  ///< degrees, the largest angle found (180 where no root was found)
  double distance = 0.0;     ///< how far from the side that angle was measured
  std::size_t side = 0;      ///< the side (0-based) it was found beside
  int missing = 0;           ///< samples where no point of the patch lies within reach of the ribbon
};

/// For patch `index`, beside each side i, at the points of its curve t = 1/8 ... 7/8: steps `step_fraction`
/// of the patch's size into the region, across the curve in the ribbon's tangent plane, finds the patch's
/// root on the line along the ribbon's normal there (within as far again on either side) and measures the
/// angle between grad F there and grad R_i. A patch that folds or bends sharply beside its boundary (its
/// function approaches the ribbon only very close to the curve) shows a large angle or no root. (\pre an
/// IPatchSurface; else all zero.) Deterministic.
BoundaryBend measure_boundary_bend(const Composite& composite, std::size_t index,
                                   double step_fraction = 0.005);

/// The farthest the patch's boundary runs outside its own region: B_j / |grad B_j| (> 0 outside) at 15
/// interior points of every side i against every other side's bound j, with the sides (0-based). A
/// patch whose region does not hold its boundary cannot reach it (the mesher fans it). Uses the
/// patch's region functions (CompositePatch::bounds, one per side; else all zero), not its surface.
struct BoundaryExit {
  double distance = 0.0;
  std::size_t side = 0, bound = 0;
};
BoundaryExit measure_boundary_exit(const Composite& composite, const CompositePatch& patch);

/// Marches the lines through patch `index` of the composite (\pre its surface is an IPatchSurface; else all
/// zero).
PatchShape measure_patch(const Composite& composite, std::size_t index, const ValidityOptions& options = {});

/// Per patch with an I-patch function (others are planes and cylinders, single sheets by construction):
/// a finding when some line meets the patch more than once inside its region, or when the patch rises
/// above one of its planar ribbons (a face plane of a setback vertex blend) by more than
/// bulge_tolerance times its size, or when measure_boundary_bend finds its normal more than
/// fold_angle degrees from its ribbon's beside a side (or no patch there): a fold beside the boundary;
/// or when a side's curve runs outside another side's bounding surface (by more than 1e-9 of the size,
/// measured as B_j / |grad B_j|): the region does not hold the patch's own boundary.
/// Deterministic; about lines * steps * n evaluations per patch.
std::vector<PatchFinding> check_patch_validity(const Composite& composite,
                                               const ValidityOptions& options = {});

}  // namespace isopatch
