// Walking a formula's tape from its result down (tape_walk.hpp).
#include "csg/tape_walk.hpp"

#include <algorithm>
#include <cstddef>

#include "expr/tape.hpp"

namespace isopatch {

using expr::Op;

int monotone_step(const expr::Instruction& in) {
  if (in.op == Op::AddC) return 1;
  if (in.op == Op::Neg || in.op == Op::RSubC) return -1;
  if (in.op == Op::MulC || in.op == Op::DivC) return in.imm > 0.0 ? 1 : (in.imm < 0.0 ? -1 : 0);
  return 0;
}

OperandWriters operand_writers(const expr::Tape& tape) {
  OperandWriters w;
  std::vector<int> writer(std::max<std::size_t>(tape.registers, expr::Tape::kVariables), -1);
  w.a.resize(tape.code.size());
  w.b.resize(tape.code.size());
  for (std::size_t i = 0; i < tape.code.size(); ++i) {
    w.a[i] = writer[tape.code[i].a];
    w.b[i] = expr::is_binary(tape.code[i].op) ? writer[tape.code[i].b] : -1;
    writer[tape.code[i].out] = static_cast<int>(i);
  }
  w.root = writer[tape.result];
  return w;
}

}  // namespace isopatch
