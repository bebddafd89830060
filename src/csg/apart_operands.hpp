#pragma once
// A shape made of two solids whose surfaces never meet: f = max(a, b) or min(a, b) at the formula's
// root, with a = 0 and b = 0 apart throughout the box (a lattice with a void, inside a curved skin:
// max(outer, min(gyroid, -inner)), or two parts side by side). Each operand's surface is then a
// surface of its own, whose every component lies wholly inside or wholly outside the other solid, so
// the shape is meshed as the operands' meshes with the components of each that the other keeps
// (api/apart_meshing.hpp), each operand by whichever path fits it (docs/lattices.md, "Skins").

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <array>
#include <cstddef>
#include <optional>

namespace isopatch {

/// The two operands of f's root and how they combine.
struct ApartOperands {
  std::array<SurfacePtr, 2> operands;  ///< a and b in the formula's order (formulas of their own)
  bool united = false;                 ///< f = min(a, b); else f = max(a, b)
};

/// Splits `f` when its root, through steps that keep order (adding a constant, scaling by a positive
/// one), is a max or min of a and b such that a = 0 and b = 0 do not meet in `box`: every sub-box of a
/// bisection of the box (its longest side halved, down to sides of `finest`, at most `most_boxes`
/// enclosures) has an interval enclosure of a or of b that excludes 0. Only formulas where a or b has a
/// max, min or abs of its own (a shape with creases) are split: a smooth f is meshed whole. Returns
/// nullopt for any other formula, a surface without an expression, or when the enclosures cannot
/// decide (surfaces that meet, or come closer than about `finest`). Nothing but enclosures is evaluated.
/// Follows the interval subdivision of Snyder, "Interval analysis for computer graphics" (SIGGRAPH 1992).
std::optional<ApartOperands> split_apart_operands(const Surface& f, const Box& box, double finest,
                                                  std::size_t most_boxes = 1u << 20);

}  // namespace isopatch
