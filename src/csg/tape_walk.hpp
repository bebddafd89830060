#pragma once
// Walking a formula's tape from its result down to its operands: which instruction wrote each operand,
// and which steps keep or reverse the order of their operand. Shared by the readers of a formula's shape
// (capped_shape.hpp, sheet_shape.hpp).

#include <vector>

#include "expr/tape.hpp"

namespace isopatch {

/// +1 for a step that keeps the order of its operand (adding a constant, scaling by a positive one),
/// -1 for one that reverses it (negating, subtracting from a constant, scaling by a negative one), 0 for
/// every other instruction.
int monotone_step(const expr::Instruction& in);

/// For every instruction, the instructions its operands read (the last to write their registers before
/// it; -1 for x, y, z and the constants), and the one that writes f (-1 when f is a variable or constant).
struct OperandWriters {
  std::vector<int> a, b;
  int root = -1;
};

/// The writers of `tape` (one pass over its code).
OperandWriters operand_writers(const expr::Tape& tape);

}  // namespace isopatch
