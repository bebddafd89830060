#pragma once
// The flat, immutable program every evaluator runs. Values live in numbered registers: x, y and z
// are registers 0, 1 and 2, each constant has a register of its own (filled before the code runs),
// and every instruction writes one register that differs from its operands' registers (so batch
// kernels may take their arrays as __restrict). Registers are reused once their value is dead, which
// keeps the batch evaluator's working set small (dag.cpp, lower()).

#include "expr/op.hpp"

#include <cstdint>
#include <vector>

namespace isopatch::expr {

struct Instruction {
  Op op;
  std::uint32_t out;  ///< register written
  std::uint32_t a;    ///< first operand register
  std::uint32_t b;    ///< second operand register (binary ops only)
  double imm;         ///< the constant of the *C forms, the exponent of Powi and PowC
};

struct ConstantRegister {
  std::uint32_t reg;
  double value;
};

struct Tape {
  static constexpr std::uint32_t kVariables = 3;  ///< registers 0, 1, 2 hold x, y, z

  std::vector<Instruction> code;
  std::vector<ConstantRegister> constants;
  std::uint32_t registers = kVariables;  ///< size of the register file
  std::uint32_t result = 0;              ///< register holding f after the code ran

  /// Instructions plus constants: the length of the program.
  std::size_t size() const { return code.size() + constants.size(); }
};

}  // namespace isopatch::expr
