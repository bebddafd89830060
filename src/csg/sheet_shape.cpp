// A sheet read from its formula (sheet_shape.hpp).
#include "csg/sheet_shape.hpp"

#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "csg/box_halves.hpp"
#include "csg/tape_walk.hpp"
#include "expr/branches.hpp"
#include "expr/evaluate.hpp"
#include "expr/tape.hpp"

namespace isopatch {

namespace {

using expr::Instruction;
using expr::Op;
using expr::Tape;

/// For every instruction, whether its value depends on an `abs` (its own or one of its operands').
std::vector<bool> reads_abs(const Tape& tape, const OperandWriters& w) {
  std::vector<bool> out(tape.code.size(), false);
  for (std::size_t i = 0; i < tape.code.size(); ++i) {
    const bool a = w.a[i] >= 0 && out[static_cast<std::size_t>(w.a[i])];
    const bool b = w.b[i] >= 0 && out[static_cast<std::size_t>(w.b[i])];
    out[i] = tape.code[i].op == Op::Abs || a || b;
  }
  return out;
}

/// The abs under f's root through order-keeping or order-reversing steps, and the order of the whole
/// path (+1 or -1); {-1, 0} when f is not of that form.
struct AbsPath {
  int node = -1;
  int order = 0;
};
AbsPath abs_under_root(const Tape& tape) {
  const OperandWriters w = operand_writers(tape);
  const std::vector<bool> with_abs = reads_abs(tape, w);
  int node = w.root;
  int order = 1;
  while (node >= 0) {
    const auto i = static_cast<std::size_t>(node);
    const Instruction& in = tape.code[i];
    if (in.op == Op::Abs) return {node, order};
    if (const int step = monotone_step(in)) {
      order *= step;
      node = w.a[i];
      continue;
    }
    if (in.op != Op::Add && in.op != Op::Sub) return {};
    // A sum or difference of the abs's side and a term free of any abs.
    const bool a = w.a[i] >= 0 && with_abs[static_cast<std::size_t>(w.a[i])];
    const bool b = w.b[i] >= 0 && with_abs[static_cast<std::size_t>(w.b[i])];
    if (a == b) return {};
    if (b && in.op == Op::Sub) order = -order;
    node = a ? w.a[i] : w.b[i];
  }
  return {};
}

/// Whether `f0`'s enclosure over `box` has the sign `sign` strictly, bisecting the box's longest side
/// down to `depth` more levels where it does not decide.
bool has_sign(const Tape& f0, const Box& box, int sign, int depth) {
  const Interval v = expr::evaluate_interval(f0, box);
  if (sign < 0 ? v.hi < 0.0 : v.lo > 0.0) return true;
  if (depth == 0 || (sign < 0 ? v.lo >= 0.0 : v.hi <= 0.0)) return false;
  const std::array<Box, 2> half = halves(box);
  return has_sign(f0, half[0], sign, depth - 1) && has_sign(f0, half[1], sign, depth - 1);
}

}  // namespace

std::optional<SheetShape> split_sheet_shape(const Surface& f, const Box& box) {
  const Expression* formula = f.expression();
  if (formula == nullptr || formula->tape().code.empty() || !box.valid()) return std::nullopt;
  const Tape& tape = formula->tape();
  const AbsPath path = abs_under_root(tape);
  if (path.node < 0) return std::nullopt;
  // f with |g| read as 0: where it has the sign opposite to the path's order, f = phi(|g|) moves away
  // from zero as |g| falls to 0, so f = 0 only where |g| is positive.
  Tape f0 = tape;
  Instruction& at_zero = f0.code[static_cast<std::size_t>(path.node)];
  at_zero = Instruction{Op::MulC, at_zero.out, at_zero.a, at_zero.a, 0.0};
  if (!has_sign(f0, box, -path.order, 9)) return std::nullopt;
  const std::vector<std::uint32_t> switches = expr::switch_instructions(tape);
  std::size_t s = 0;
  while (s < switches.size() && switches[s] != static_cast<std::uint32_t>(path.node)) ++s;
  if (s == switches.size()) return std::nullopt;
  SheetShape sheet;
  for (std::int8_t side = 0; side < 2; ++side) {
    expr::BranchChoice choice(switches.size(), expr::kOpen);
    choice[s] = side;
    sheet.walls[static_cast<std::size_t>(side)] = expression_surface(
        Expression(std::make_shared<const Tape>(expr::specialise(tape, switches, choice))), box,
        side == 0 ? "the sheet's wall where its middle function is positive"
                  : "the sheet's wall where its middle function is negative");
  }
  return sheet;
}

}  // namespace isopatch
