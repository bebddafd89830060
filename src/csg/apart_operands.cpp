// A shape of two solids whose surfaces never meet, read from its formula (apart_operands.hpp).
#include "csg/apart_operands.hpp"

#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

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

/// Proves a = 0 and b = 0 apart over `box` by bisection (see split_apart_operands()); `budget` counts
/// the enclosures left.
class ApartProof {
 public:
  ApartProof(const Tape& a, const Tape& b, double finest, std::size_t budget)
      : a_(a), b_(b), finest_(finest), budget_(budget) {}

  bool apart(const Box& box) {
    if (budget_ == 0) return false;
    --budget_;
    const Interval va = expr::evaluate_interval(a_, box);
    if (va.lo > 0.0 || va.hi < 0.0) return true;
    const Interval vb = expr::evaluate_interval(b_, box);
    if (vb.lo > 0.0 || vb.hi < 0.0) return true;
    const Vec3 size = box.hi - box.lo;
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (size[k] > size[axis]) axis = k;
    // Both enclosures hold 0 (or are not finite) on a box as small as asked: undecided.
    if (!(size[axis] > finest_)) return false;
    Box low = box, high = box;
    const double mid = 0.5 * (box.lo[axis] + box.hi[axis]);
    low.hi[axis] = mid;
    high.lo[axis] = mid;
    return apart(low) && apart(high);
  }

 private:
  const Tape& a_;
  const Tape& b_;
  double finest_;
  std::size_t budget_;
};

/// The tape of op(a, b): x, y, z copied for b first (a's code may reuse their registers), then a's code,
/// then b's with its registers moved past a's, then the operation.
Tape combined(Op op, const Tape& a, const Tape& b) {
  const std::uint32_t base = a.registers;
  Tape out;
  out.registers = base + b.registers + 1;
  for (std::uint32_t k = 0; k < Tape::kVariables; ++k)
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

/// The node under f's root through increasing steps, or -1.
int root_node(const Tape& tape, const OperandWriters& writers) {
  int node = writers.root;
  while (node >= 0 && monotone_step(tape.code[static_cast<std::size_t>(node)]) > 0)
    node = writers.a[static_cast<std::size_t>(node)];
  return node;
}

/// f with the switch `node` (an index into the code) fixed to `side`, the instructions f no longer
/// needs removed.
Tape with_branch(const Tape& tape, const std::vector<std::uint32_t>& switches, int node, std::int8_t side) {
  expr::BranchChoice choice(switches.size(), expr::kOpen);
  for (std::size_t s = 0; s < switches.size(); ++s)
    if (switches[s] == static_cast<std::uint32_t>(node)) choice[s] = side;
  return expr::specialise(tape, switches, choice);
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
      const std::vector<std::uint32_t> switches = expr::switch_instructions(tape);
      const Tape on_p = with_branch(tape, switches, root, 0), on_q = with_branch(tape, switches, root, 1);
      const std::vector<std::uint32_t> p_switches = expr::switch_instructions(on_p);
      const std::vector<std::uint32_t> q_switches = expr::switch_instructions(on_q);
      const OperandWriters wp = operand_writers(on_p), wq = operand_writers(on_q);
      const int p_node = root_node(on_p, wp), q_node = root_node(on_q, wq);
      if (p_node < 0 || q_node < 0) return std::nullopt;
      const Tape t = with_branch(on_p, p_switches, p_node, i);
      const Tape x = with_branch(on_p, p_switches, p_node, static_cast<std::int8_t>(1 - i));
      const Tape y = with_branch(on_q, q_switches, q_node, static_cast<std::int8_t>(1 - j));
      return combined(inner, t, combined(outer, x, y));
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
  const auto s = static_cast<std::size_t>(
      std::find(switches.begin(), switches.end(), static_cast<std::uint32_t>(node)) - switches.begin());
  if (s == switches.size()) return std::nullopt;
  std::array<Tape, 2> operand;
  for (std::int8_t k = 0; k < 2; ++k)
    operand[static_cast<std::size_t>(k)] = with_branch(tape, switches, node, k);
  if (!has_switch(operand[0]) && !has_switch(operand[1])) return std::nullopt;
  ApartProof proof(operand[0], operand[1], finest, most_boxes);
  if (!proof.apart(box)) return std::nullopt;
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
  const std::optional<Tape> other = factored(formula->tape());
  if (!other) return std::nullopt;
  return split_tape(*other, box, finest, most_boxes);
}

}  // namespace isopatch
