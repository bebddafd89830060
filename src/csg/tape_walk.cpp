// Walking a formula's tape from its result down, and composing tapes (tape_walk.hpp).
#include "csg/tape_walk.hpp"

#include <algorithm>
#include <cstddef>

#include "expr/branches.hpp"
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

int root_node(const expr::Tape& tape, const OperandWriters& writers) {
  int node = writers.root;
  while (node >= 0 && monotone_step(tape.code[static_cast<std::size_t>(node)]) > 0)
    node = writers.a[static_cast<std::size_t>(node)];
  return node;
}

expr::Tape negated(expr::Tape tape) {
  const std::uint32_t out = tape.registers++;
  tape.code.push_back(expr::Instruction{Op::Neg, out, tape.result, tape.result, 0.0});
  tape.result = out;
  return tape;
}

expr::Tape combined(Op op, const expr::Tape& a, const expr::Tape& b) {
  const std::uint32_t base = a.registers;
  expr::Tape out;
  out.registers = base + b.registers + 1;
  for (std::uint32_t k = 0; k < expr::Tape::kVariables; ++k)
    out.code.push_back(expr::Instruction{Op::AddC, base + k, k, k, 0.0});
  out.code.insert(out.code.end(), a.code.begin(), a.code.end());
  out.constants = a.constants;
  for (expr::Instruction in : b.code) {
    in.out += base;
    in.a += base;
    in.b += base;
    out.code.push_back(in);
  }
  for (expr::ConstantRegister c : b.constants) {
    c.reg += base;
    out.constants.push_back(c);
  }
  out.result = base + b.registers;
  out.code.push_back(expr::Instruction{op, out.result, a.result, base + b.result, 0.0});
  return out;
}

expr::Tape with_branch(const expr::Tape& tape, const std::vector<std::uint32_t>& switches, int node,
                       std::int8_t side) {
  expr::BranchChoice choice(switches.size(), expr::kOpen);
  for (std::size_t s = 0; s < switches.size(); ++s)
    if (switches[s] == static_cast<std::uint32_t>(node)) choice[s] = side;
  return expr::specialise(tape, switches, choice);
}

}  // namespace isopatch
