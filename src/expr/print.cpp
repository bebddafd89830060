// Printing a compiled expression back in the expression language. Values used more than once become
// definitions (v7 = ...), so the text stays linear in the tape size however much is shared.
#include "expr/tape.hpp"

#include <isopatch/expression.hpp>

#include <charconv>
#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace isopatch {
namespace {

/// Concatenation by appending (GCC 12 warns falsely, -Wrestrict, on chains of "x" + std::string).
std::string cat(std::initializer_list<std::string_view> parts) {
  std::size_t size = 0;
  for (const std::string_view p : parts) size += p.size();
  std::string s;
  s.reserve(size);
  for (const std::string_view p : parts) s.append(p);
  return s;
}

std::string number(double v) {
  if (std::isnan(v)) return "(0/0)";
  if (std::isinf(v)) return v > 0 ? "(1/0)" : "(-1/0)";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);  // shortest exact form
  const std::string_view text(buffer, static_cast<std::size_t>(result.ptr - buffer));
  return std::signbit(v) ? cat({"(", text, ")"}) : std::string(text);
}

std::string operation(const expr::Instruction& in, const std::string& a, const std::string& b) {
  using expr::Op;
  const std::string c = number(in.imm);
  switch (in.op) {
    case Op::Neg:
      return cat({"(-", a, ")"});
    case Op::Square:
      return cat({"(", a, " ^ 2)"});
    case Op::Powi:
    case Op::PowC:
      return cat({"(", a, " ^ ", c, ")"});
    case Op::AddC:
      if (std::signbit(in.imm) && !std::isnan(in.imm)) return cat({"(", a, " - ", number(-in.imm), ")"});
      return cat({"(", a, " + ", c, ")"});
    case Op::MulC:
      return cat({"(", c, " * ", a, ")"});
    case Op::RSubC:
      return cat({"(", c, " - ", a, ")"});
    case Op::DivC:
      return cat({"(", a, " / ", c, ")"});
    case Op::RDivC:
      return cat({"(", c, " / ", a, ")"});
    case Op::Add:
      return cat({"(", a, " + ", b, ")"});
    case Op::Sub:
      return cat({"(", a, " - ", b, ")"});
    case Op::Mul:
      return cat({"(", a, " * ", b, ")"});
    case Op::Div:
      return cat({"(", a, " / ", b, ")"});
    case Op::Pow:
      return cat({"(", a, " ^ ", b, ")"});
    default:
      break;
  }
  const std::string_view name = expr::function_name(in.op);
  return expr::is_binary(in.op) ? cat({name, "(", a, ", ", b, ")"}) : cat({name, "(", a, ")"});
}

}  // namespace

std::string to_string(const Expression& expression) {
  const expr::Tape& tape = expression.tape();
  // Value numbers: 0..2 the variables, then the constants, then one per instruction.
  const std::size_t first_instruction = 3 + tape.constants.size();
  std::vector<std::size_t> value_in(tape.registers, 0);
  std::vector<std::string> text(first_instruction + tape.code.size());
  for (std::size_t k = 0; k < 3; ++k) {
    value_in[k] = k;
    text[k] = std::string(1, "xyz"[k]);
  }
  for (std::size_t i = 0; i < tape.constants.size(); ++i) {
    value_in[tape.constants[i].reg] = 3 + i;
    text[3 + i] = number(tape.constants[i].value);
  }
  std::vector<int> uses(text.size(), 0);
  {
    std::vector<std::size_t> current = value_in;
    for (std::size_t i = 0; i < tape.code.size(); ++i) {
      const expr::Instruction& in = tape.code[i];
      ++uses[current[in.a]];
      if (expr::is_binary(in.op)) ++uses[current[in.b]];
      current[in.out] = first_instruction + i;
    }
  }
  std::string definitions;
  for (std::size_t i = 0; i < tape.code.size(); ++i) {
    const expr::Instruction& in = tape.code[i];
    const std::size_t id = first_instruction + i;
    std::string t = operation(in, text[value_in[in.a]], expr::is_binary(in.op) ? text[value_in[in.b]] : "");
    if (uses[id] > 1) {
      const std::string name = cat({"v", std::to_string(i)});
      definitions += cat({name, " = ", t, ";\n"});
      t = name;
    }
    text[id] = std::move(t);
    value_in[in.out] = id;
  }
  return cat({definitions, text[value_in[tape.result]]});
}

}  // namespace isopatch
