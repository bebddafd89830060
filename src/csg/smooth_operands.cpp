// The smooth operands of a CSG formula (smooth_operands.hpp).
#include "csg/smooth_operands.hpp"

#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

#include <memory>
#include <string>
#include <utility>

#include "csg/tape_walk.hpp"
#include "expr/branches.hpp"

namespace isopatch {

namespace {

using expr::Tape;

/// Appends the operands of `tape` to `out`; false once there would be more than `most`.
bool collect(const Tape& tape, std::size_t most, std::vector<Tape>& out) {
  const std::vector<std::uint32_t> switches = expr::switch_instructions(tape);
  if (switches.empty()) {
    if (out.size() >= most) return false;
    out.push_back(tape);
    return true;
  }
  // The last switch of the code reads no other switch's result after it: the root-most one, whose
  // fixing drops the other side's subexpression whole.
  const int node = static_cast<int>(switches.back());
  for (std::int8_t side = 0; side < 2; ++side)
    if (!collect(with_branch(tape, switches, node, side), most, out)) return false;
  return true;
}

}  // namespace

std::optional<std::vector<SurfacePtr>> smooth_operands(const Surface& f, const Box& box, std::size_t most) {
  const Expression* formula = f.expression();
  if (formula == nullptr || formula->tape().code.empty() ||
      expr::switch_instructions(formula->tape()).empty())
    return std::nullopt;
  std::vector<Tape> tapes;
  if (!collect(formula->tape(), most, tapes)) return std::nullopt;
  std::vector<SurfacePtr> out;
  out.reserve(tapes.size());
  for (std::size_t k = 0; k < tapes.size(); ++k)
    out.push_back(expression_surface(Expression(std::make_shared<const Tape>(std::move(tapes[k]))), box,
                                     "operand " + std::to_string(k + 1)));
  return out;
}

}  // namespace isopatch
