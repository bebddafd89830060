#pragma once
// Walking a formula's tape from its result down to its operands: which instruction wrote each operand,
// and which steps keep or reverse the order of their operand; and composing tapes (a negation, a max or
// min of two, a branch fixed). Shared by the readers of a formula's shape (capped_shape.hpp,
// sheet_shape.hpp, apart_operands.hpp).

#include <cstdint>
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

/// The instruction under f's root through increasing steps (monotone_step() > 0), or -1.
int root_node(const expr::Tape& tape, const OperandWriters& writers);

/// `tape` with its result negated (one instruction appended).
expr::Tape negated(expr::Tape tape);

/// The tape of op(a, b) (a binary op): x, y, z copied for b first (a's code may reuse their registers),
/// then a's code, then b's with its registers moved past a's, then the operation. Computes exactly what
/// a and b compute.
expr::Tape combined(expr::Op op, const expr::Tape& a, const expr::Tape& b);

/// f with the switch (min, max or abs) at instruction `node` fixed to `side` (0: its first operand), the
/// instructions f no longer needs removed (expr::specialise()); f itself when `node` is no switch.
/// \pre switches == expr::switch_instructions(tape).
expr::Tape with_branch(const expr::Tape& tape, const std::vector<std::uint32_t>& switches, int node,
                       std::int8_t side);

}  // namespace isopatch
