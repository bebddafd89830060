// The table of callable functions.
#include "expr/op.hpp"

#include <array>

namespace isopatch::expr {
namespace {

constexpr std::array<Function, 18> kFunctions = {{
    {"sin", Op::Sin, 1},
    {"cos", Op::Cos, 1},
    {"tan", Op::Tan, 1},
    {"asin", Op::Asin, 1},
    {"acos", Op::Acos, 1},
    {"atan", Op::Atan, 1},
    {"atan2", Op::Atan2, 2},
    {"sinh", Op::Sinh, 1},
    {"cosh", Op::Cosh, 1},
    {"tanh", Op::Tanh, 1},
    {"exp", Op::Exp, 1},
    {"log", Op::Log, 1},
    {"sqrt", Op::Sqrt, 1},
    {"abs", Op::Abs, 1},
    {"min", Op::Min, 2, true},
    {"max", Op::Max, 2, true},
    {"pow", Op::Pow, 2},
    {"hypot", Op::Hypot, 2},
}};

}  // namespace

std::span<const Function> functions() {
  return kFunctions;
}

const Function* find_function(std::string_view name) {
  for (const Function& f : kFunctions)
    if (f.name == name) return &f;
  return nullptr;
}

std::string_view function_name(Op op) {
  for (const Function& f : kFunctions)
    if (f.op == op) return f.name;
  return {};
}

}  // namespace isopatch::expr
