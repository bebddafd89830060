#pragma once
// The instruction set shared by the DAG, the tape and every evaluator, and the table of the functions a
// formula may call. One enum keeps the parser, the folding, the printer and the evaluators in step.

#include <cstdint>
#include <span>
#include <string_view>

namespace isopatch::expr {

enum class Op : std::uint8_t {
  // Leaves: only in the DAG (on the tape variables and constants are registers).
  Var,    ///< imm = axis (0, 1, 2)
  Const,  ///< imm = the value
  // Unary, operand a. `imm` holds the constant c of the *C forms and the exponent of Powi / PowC.
  Neg,
  Square,  ///< a * a
  Powi,    ///< a^n for an odd integer n >= 3, by repeated squaring (scalar.hpp ipow)
  PowC,    ///< std::pow(a, c) for a constant c that is not a small integer
  AddC,    ///< a + c
  MulC,    ///< a * c
  RSubC,   ///< c - a
  DivC,    ///< a / c
  RDivC,   ///< c / a
  Sqrt,
  Exp,
  Log,
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Sinh,
  Cosh,
  Tanh,
  Abs,
  // Binary, operands a and b.
  Add,
  Sub,
  Mul,
  Div,
  Pow,    ///< std::pow(a, b), both varying (or a constant base)
  Atan2,  ///< atan2(a = y, b = x)
  Hypot,
  Min,  ///< b < a ? b : a
  Max,  ///< a < b ? b : a
};

constexpr bool is_leaf(Op op) {
  return op == Op::Var || op == Op::Const;
}
constexpr bool is_binary(Op op) {
  return op >= Op::Add;
}
constexpr bool is_commutative(Op op) {
  return op == Op::Add || op == Op::Mul || op == Op::Hypot || op == Op::Min || op == Op::Max;
}

/// A function a formula may call: `name(arg, ...)`. min and max take two or more arguments.
struct Function {
  std::string_view name;
  Op op;
  int arity;  ///< number of arguments; for min and max the minimum
  bool variadic = false;
};

/// Every callable function, in a fixed order.
std::span<const Function> functions();

/// The function of that name, or nullptr.
const Function* find_function(std::string_view name);

/// The name a unary or binary function op is written with (sin, atan2, ...); empty for operators.
std::string_view function_name(Op op);

}  // namespace isopatch::expr
