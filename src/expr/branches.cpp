// Switches of a tape and their specialisation (branches.hpp).
#include "expr/branches.hpp"

#include "expr/scalar.hpp"

#include <algorithm>
#include <utility>

namespace isopatch::expr {

namespace {

bool is_switch(Op op) {
  return op == Op::Min || op == Op::Max || op == Op::Abs;
}

/// Which instructions f needs: walking back from the result, an instruction is live when a live
/// instruction reads its output register after it and before the register is written again. A fixed
/// switch (choice >= 0) reads only its branch's operand.
std::vector<bool> live_instructions(const Tape& tape, const std::vector<std::int8_t>& fixed) {
  std::vector<bool> needed(tape.registers, false);
  needed[tape.result] = true;
  std::vector<bool> live(tape.code.size(), false);
  for (std::size_t i = tape.code.size(); i-- > 0;) {
    const Instruction& in = tape.code[i];
    if (!needed[in.out]) continue;
    live[i] = true;
    needed[in.out] = false;
    const std::int8_t c = fixed[i];
    if (c == kOpen || in.op == Op::Abs) {
      needed[in.a] = true;
      if (is_binary(in.op) && c == kOpen) needed[in.b] = true;
    } else {
      needed[c == 0 ? in.a : in.b] = true;
    }
  }
  return live;
}

}  // namespace

std::vector<std::uint32_t> switch_instructions(const Tape& tape) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < tape.code.size(); ++i)
    if (is_switch(tape.code[i].op)) out.push_back(static_cast<std::uint32_t>(i));
  return out;
}

SwitchValues switch_values(const Tape& tape, const Vec3& p) {
  SwitchValues out;
  out.taken.assign(tape.code.size(), kOpen);
  out.operands.assign(tape.code.size(), {0.0, 0.0});
  std::vector<double> r(std::max<std::size_t>(tape.registers, Tape::kVariables), 0.0);
  r[0] = p.x();
  r[1] = p.y();
  r[2] = p.z();
  for (const ConstantRegister& c : tape.constants) r[c.reg] = c.value;
  for (std::size_t i = 0; i < tape.code.size(); ++i) {
    const Instruction& in = tape.code[i];
    const double a = r[in.a], b = r[in.b];
    // The branch the evaluators take (scalar.hpp: min is b < a ? b : a, max is a < b ? b : a).
    if (in.op == Op::Min) out.taken[i] = b < a ? 1 : 0;
    if (in.op == Op::Max) out.taken[i] = a < b ? 1 : 0;
    if (in.op == Op::Abs) out.taken[i] = a < 0.0 ? 1 : 0;
    out.operands[i] = {a, b};
    r[in.out] = apply(in.op, a, b, in.imm);
  }
  return out;
}

BranchChoice active_branches(const Tape& tape, const std::vector<std::uint32_t>& switches, const Vec3& p) {
  return live_choice(tape, switches, all_branches(switches, switch_values(tape, p)));
}

BranchChoice all_branches(const std::vector<std::uint32_t>& switches, const SwitchValues& values) {
  BranchChoice choice(switches.size(), kOpen);
  for (std::size_t s = 0; s < switches.size(); ++s) choice[s] = values.taken[switches[s]];
  return choice;
}

BranchChoice live_choice(const Tape& tape, const std::vector<std::uint32_t>& switches, BranchChoice full) {
  std::vector<std::int8_t> fixed(tape.code.size(), kOpen);
  for (std::size_t s = 0; s < switches.size(); ++s) fixed[switches[s]] = full[s];
  const std::vector<bool> live = live_instructions(tape, fixed);
  for (std::size_t s = 0; s < switches.size(); ++s)
    if (!live[switches[s]]) full[s] = kOpen;
  return full;
}

int failing_switch(const Tape& tape, const std::vector<std::uint32_t>& switches, const BranchChoice& choice,
                   const SwitchValues& values, double tolerance) {
  for (std::size_t s = 0; s < switches.size(); ++s) {
    const std::int8_t c = choice[s];
    if (c == kOpen) continue;
    const Instruction& in = tape.code[switches[s]];
    const auto [a, b] = values.operands[switches[s]];
    bool holds = true;
    if (in.op == Op::Min) holds = c == 0 ? a <= b + tolerance : b <= a + tolerance;
    if (in.op == Op::Max) holds = c == 0 ? a >= b - tolerance : b >= a - tolerance;
    if (in.op == Op::Abs) holds = c == 0 ? a >= -tolerance : a <= tolerance;
    if (!holds) return static_cast<int>(s);
  }
  return -1;
}

std::vector<int> open_live_switches(const Tape& tape, const std::vector<std::uint32_t>& switches,
                                    const std::vector<std::int8_t>& decided) {
  const std::vector<bool> live = live_instructions(tape, decided);
  std::vector<int> out;
  for (std::size_t s = 0; s < switches.size(); ++s)
    if (live[switches[s]] && decided[switches[s]] == kOpen) out.push_back(static_cast<int>(s));
  return out;
}

Tape specialise(const Tape& tape, const std::vector<std::uint32_t>& switches, const BranchChoice& choice) {
  std::vector<std::int8_t> fixed(tape.code.size(), kOpen);
  for (std::size_t s = 0; s < switches.size(); ++s) fixed[switches[s]] = choice[s];
  const std::vector<bool> live = live_instructions(tape, fixed);
  Tape out;
  out.constants = tape.constants;
  out.registers = tape.registers;
  out.result = tape.result;
  for (std::size_t i = 0; i < tape.code.size(); ++i) {
    if (!live[i]) continue;
    Instruction in = tape.code[i];
    const std::int8_t c = fixed[i];
    if (c != kOpen) {
      if (in.op == Op::Abs) {
        in.op = c == 0 ? Op::AddC : Op::Neg;
      } else {
        in.op = Op::AddC;
        if (c == 1) in.a = in.b;
      }
      in.imm = 0.0;
      in.b = in.a;
    }
    out.code.push_back(in);
  }
  return out;
}

}  // namespace isopatch::expr
