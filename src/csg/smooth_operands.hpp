#pragma once
/// \file smooth_operands.hpp
/// The smooth operands of a CSG formula: f with every min, max and abs fixed to one branch. Each is f as
/// it reads where it takes those branches (the steps outside the switches kept), so a point where an
/// operand is the branch f takes has the operand's value there. docs/creases.md.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace isopatch {

/// The operands of the formula of `f` (Surface::expression()), found by fixing its root-most switch to
/// either side and each side's the same way until none is left: once per leaf of the tree of switches (a
/// subexpression shared by two switches may give an operand twice). nullopt when f is no formula, has no
/// switch, or has more than `most` operands. The surfaces take `box` as their box. Deterministic.
/// Follows no paper. \throw nothing beyond allocation.
std::optional<std::vector<SurfacePtr>> smooth_operands(const Surface& f, const Box& box, std::size_t most);

}  // namespace isopatch
