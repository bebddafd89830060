// A shape of two solids whose surfaces never meet, read from its formula (apart_operands.hpp).
#include "csg/apart_operands.hpp"

#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

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

using expr::Op;
using expr::Tape;

/// Whether `tape` has a max, min or abs: a formula that may have creases.
bool has_switch(const Tape& tape) {
  return !expr::switch_instructions(tape).empty();
}

/// Whether a = 0 and b = 0 do not meet in `box`: on every box of the bisection, the enclosure of a or of
/// b excludes 0 (see split_apart_operands()).
bool apart(const Tape& a, const Tape& b, const Box& box, double finest, std::size_t budget) {
  const auto excludes_zero = [](const Tape& f, const Box& cell) {
    const Interval v = expr::evaluate_interval(f, cell);
    return v.lo > 0.0 || v.hi < 0.0;
  };
  return settled_throughout(
      box, finest, budget, [&](const Box& cell) { return excludes_zero(a, cell) || excludes_zero(b, cell); });
}

/// The four leaf tapes of f = op(op'(l00, l01), op'(l10, l11)) at the switch `root` (leaves[k][i]: the
/// root's branch k, then the inner switch's branch i), each with f's steps above the root; nullopt when a
/// side has no switch under its root.
std::optional<std::array<std::array<Tape, 2>, 2>> leaves_of_sides(const Tape& tape, int root) {
  const std::vector<std::uint32_t> switches = expr::switch_instructions(tape);
  std::array<std::array<Tape, 2>, 2> leaves;
  for (std::int8_t k = 0; k < 2; ++k) {
    // The root's branch fixed leaves a copy of it (u + 0) over the inner switch.
    const Tape side = with_branch(tape, switches, root, k);
    const int node = root_node(side, operand_writers(side));
    if (node < 0) return std::nullopt;
    const std::vector<std::uint32_t> side_switches = expr::switch_instructions(side);
    for (std::int8_t i = 0; i < 2; ++i)
      leaves[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)] =
          with_branch(side, side_switches, node, i);
  }
  return leaves;
}

/// f = min(max(X, T), max(T, Y)) (T shared, in any position; through increasing steps at the root) as
/// max(T, min(X, Y)), the same function (min and max distribute over each other); likewise
/// max(min(X, T), min(T, Y)) as min(T, max(X, Y)). A skin written as the outer body less its offset,
/// united with a lattice intersected with the body, so becomes the body intersected with the union of
/// the lattice and the offset's complement, whose operands may stay apart. Nullopt for other formulas.
std::optional<Tape> factored(const Tape& tape) {
  const OperandWriters w = operand_writers(tape);
  const int root = root_node(tape, w);
  if (root < 0) return std::nullopt;
  const Op outer = tape.code[static_cast<std::size_t>(root)].op;
  if (outer != Op::Min && outer != Op::Max) return std::nullopt;
  const Op inner = outer == Op::Min ? Op::Max : Op::Min;
  const int p = w.a[static_cast<std::size_t>(root)], q = w.b[static_cast<std::size_t>(root)];
  if (p < 0 || q < 0 || tape.code[static_cast<std::size_t>(p)].op != inner ||
      tape.code[static_cast<std::size_t>(q)].op != inner)
    return std::nullopt;
  const auto up = static_cast<std::size_t>(p), uq = static_cast<std::size_t>(q);
  for (std::int8_t i = 0; i < 2; ++i)
    for (std::int8_t j = 0; j < 2; ++j) {
      const int shared = i == 0 ? w.a[up] : w.b[up];
      if (shared < 0 || shared != (j == 0 ? w.a[uq] : w.b[uq])) continue;
      // step(T), step(X) and step(Y): f with the root's branch and the inner one fixed.
      const auto leaves = leaves_of_sides(tape, root);
      if (!leaves) return std::nullopt;
      const std::array<Tape, 2>&on_p = (*leaves)[0], &on_q = (*leaves)[1];
      return combined(
          inner, on_p[static_cast<std::size_t>(i)],
          combined(outer, on_p[static_cast<std::size_t>(1 - i)], on_q[static_cast<std::size_t>(1 - j)]));
    }
  return std::nullopt;
}

/// Whether the instructions `i` and `j` compute exact negations of each other: -u and u, u + c and
/// -c - u, c * u and -c * u, u - v and v - u (u and v values of instructions; rounding is symmetric).
bool negations(const Tape& tape, const OperandWriters& w, int i, int j) {
  if (i < 0 || j < 0) return false;
  const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
  const expr::Instruction &a = tape.code[ui], &b = tape.code[uj];
  if ((a.op == Op::Neg && w.a[ui] == j) || (b.op == Op::Neg && w.a[uj] == i)) return true;
  const bool same_operand = w.a[ui] >= 0 && w.a[ui] == w.a[uj];
  if (same_operand && ((a.op == Op::AddC && b.op == Op::RSubC) || (a.op == Op::RSubC && b.op == Op::AddC)))
    return b.imm == -a.imm;
  if (same_operand && a.op == Op::MulC && b.op == Op::MulC) return b.imm == -a.imm;
  return a.op == Op::Sub && b.op == Op::Sub && w.a[ui] >= 0 && w.b[ui] >= 0 && w.a[ui] == w.b[uj] &&
         w.b[ui] == w.a[uj];
}

/// Whether s <= 0 implies t < 0 throughout `box` (the solid s < 0 lies inside t < 0, apart from its
/// surface): on every box of the bisection, s > 0 or t < 0 by the enclosures.
bool inside(const Tape& s, const Tape& t, const Box& box, double finest, std::size_t budget) {
  return settled_throughout(box, finest, budget, [&](const Box& cell) {
    return expr::evaluate_interval(s, cell).lo > 0.0 || expr::evaluate_interval(t, cell).hi < 0.0;
  });
}

/// f = min(max(X, s), max(t, -s)) (in any order, the root a min itself) with the solid s < 0 inside
/// t < 0 in `box`: an infill X < 0 of the inner body s < 0 united with the skin between it and the
/// outer body t < 0. Its solid is that of max(t, min(X, -s)), whose surface lacks only the face s = 0
/// the two operands share (where f = 0 inside the solid without changing sign); nullopt for other
/// formulas or when the inclusion is not proved.
std::optional<Tape> factored_by_inclusion(const Tape& tape, const Box& box, double finest,
                                          std::size_t budget) {
  const OperandWriters w = operand_writers(tape);
  const int root = w.root;
  if (root < 0 || tape.code[static_cast<std::size_t>(root)].op != Op::Min) return std::nullopt;
  const int sides[2] = {w.a[static_cast<std::size_t>(root)], w.b[static_cast<std::size_t>(root)]};
  for (const int side : sides)
    if (side < 0 || tape.code[static_cast<std::size_t>(side)].op != Op::Max) return std::nullopt;
  for (std::int8_t infill = 0; infill < 2; ++infill) {
    const auto p = static_cast<std::size_t>(sides[infill]), q = static_cast<std::size_t>(sides[1 - infill]);
    for (std::int8_t i = 0; i < 2; ++i)
      for (std::int8_t j = 0; j < 2; ++j) {
        if (!negations(tape, w, i == 0 ? w.a[p] : w.b[p], j == 0 ? w.a[q] : w.b[q])) continue;
        const auto leaves = leaves_of_sides(tape, root);
        if (!leaves) return std::nullopt;
        const std::array<Tape, 2>&on_p = (*leaves)[static_cast<std::size_t>(infill)],
                               &on_q = (*leaves)[static_cast<std::size_t>(1 - infill)];
        const Tape& inner = on_p[static_cast<std::size_t>(i)];
        const Tape& lattice = on_p[static_cast<std::size_t>(1 - i)];
        const Tape& minus_inner = on_q[static_cast<std::size_t>(j)];
        const Tape& outer = on_q[static_cast<std::size_t>(1 - j)];
        if (!inside(inner, outer, box, finest, budget)) continue;
        return combined(Op::Max, outer, combined(Op::Min, lattice, minus_inner));
      }
  }
  return std::nullopt;
}

/// split_apart_operands() of one tape.
std::optional<ApartOperands> split_tape(const Tape& tape, const Box& box, double finest,
                                        std::size_t most_boxes) {
  const OperandWriters writers = operand_writers(tape);
  const int node = root_node(tape, writers);
  if (node < 0) return std::nullopt;
  const Op root = tape.code[static_cast<std::size_t>(node)].op;
  if (root != Op::Max && root != Op::Min) return std::nullopt;
  const std::vector<std::uint32_t> switches = expr::switch_instructions(tape);
  std::array<Tape, 2> operand;
  for (std::int8_t k = 0; k < 2; ++k)
    operand[static_cast<std::size_t>(k)] = with_branch(tape, switches, node, k);
  if (!has_switch(operand[0]) && !has_switch(operand[1])) return std::nullopt;
  if (!apart(operand[0], operand[1], box, finest, most_boxes)) return std::nullopt;
  ApartOperands out;
  out.united = root == Op::Min;
  for (std::size_t k = 0; k < 2; ++k)
    out.operands[k] = expression_surface(Expression(std::make_shared<const Tape>(std::move(operand[k]))), box,
                                         k == 0 ? "the first operand" : "the second operand");
  return out;
}

}  // namespace

std::optional<ApartOperands> split_apart_operands(const Surface& f, const Box& box, double finest,
                                                  std::size_t most_boxes) {
  const Expression* formula = f.expression();
  if (formula == nullptr || formula->tape().code.empty() || !box.valid() || !(finest > 0.0))
    return std::nullopt;
  if (std::optional<ApartOperands> split = split_tape(formula->tape(), box, finest, most_boxes)) return split;
  if (const std::optional<Tape> other = factored(formula->tape()))
    if (std::optional<ApartOperands> split = split_tape(*other, box, finest, most_boxes)) return split;
  if (const std::optional<Tape> other = factored_by_inclusion(formula->tape(), box, finest, most_boxes))
    return split_tape(*other, box, finest, most_boxes);
  return std::nullopt;
}

}  // namespace isopatch
