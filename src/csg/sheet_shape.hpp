#pragma once
// A sheet read from its formula: f = phi(|g|), one `abs` reached from f's root through steps that keep
// or reverse order (adding a constant or a term free of that abs, scaling by a constant), such as the
// wall of a lattice, abs(gyroid) - t. Its surface is two level sets of g, g = c and g = -c with c > 0
// (c may vary in space), which never meet: each is meshed as a smooth surface of its own
// (api/sheet_meshing.hpp), so that the mesher's cells never have to hold both walls of a sheet thinner
// than an edge (docs/lattices.md, "Sheets").

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <array>
#include <optional>

namespace isopatch {

/// The two walls of a sheet: f with |g| read as +g (the wall where g > 0) and as -g (where g < 0). Each
/// is a formula of its own, equal to f on its side of g = 0, so its gradient points out of the solid
/// f < 0 there: the two meshes together are f = 0, outward.
struct SheetShape {
  std::array<SurfacePtr, 2> walls;
};

/// Splits `f` when it is a sheet as above and f = 0 stays off g = 0 throughout `box`: f with |g| read as
/// 0 has, over the box (bisected up to 512 sub-boxes where one interval does not decide), the sign
/// opposite to the order of the steps (so f = phi(|g|) can vanish only where |g| > 0, and each wall's
/// zero set lies on its own side). Returns nullopt for any other formula, a formula without an
/// expression, or when the intervals cannot decide. Nothing is evaluated but those intervals.
std::optional<SheetShape> split_sheet_shape(const Surface& f, const Box& box);

}  // namespace isopatch
