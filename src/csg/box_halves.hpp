#pragma once
// The two halves of a box across its longest side: the step of the interval bisections that prove
// a formula's shape (sheet_shape.cpp, apart_operands.cpp).

#include <isopatch/geometry.hpp>

#include <array>
#include <cstddef>

namespace isopatch {

/// The box's longest side (the first of equal ones): its axis and length.
struct LongestSide {
  int axis = 0;
  double length = 0.0;
};

inline LongestSide longest_side(const Box& box) {
  const Vec3 size = box.hi - box.lo;
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (size[k] > size[axis]) axis = k;
  return {axis, size[axis]};
}

/// `box` cut in two at the middle of its longest side (lower half first).
inline std::array<Box, 2> halves(const Box& box) {
  const int axis = longest_side(box).axis;
  std::array<Box, 2> out{box, box};
  out[0].hi[axis] = out[1].lo[axis] = 0.5 * (box.lo[axis] + box.hi[axis]);
  return out;
}

/// Whether `settled` holds on every box of a bisection of `box` (halves() where it does not, down to
/// boxes whose longest side is `finest` or less, where it must), spending one of `budget` per box
/// tried: false when a smallest box is not settled or the budget runs out.
template <class Settled>
bool settled_throughout(const Box& box, double finest, std::size_t& budget, const Settled& settled) {
  if (budget == 0) return false;
  --budget;
  if (settled(box)) return true;
  if (!(longest_side(box).length > finest)) return false;
  const std::array<Box, 2> half = halves(box);
  return settled_throughout(half[0], finest, budget, settled) &&
         settled_throughout(half[1], finest, budget, settled);
}

}  // namespace isopatch
