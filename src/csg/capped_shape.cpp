// A smooth solid capped by a convex polyhedron, read from its formula (capped_shape.hpp).
#include "csg/capped_shape.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

#include "csg/tape_walk.hpp"
#include "expr/branches.hpp"
#include "expr/tape.hpp"

namespace isopatch {

namespace {

using expr::BranchChoice;
using expr::Instruction;
using expr::Op;
using expr::Tape;

/// What a register holds as a function of x, y, z: a constant, an affine function or anything else.
enum class Kind : std::uint8_t { Constant, Affine, Other };

Kind join(Kind a, Kind b) {
  return std::max(a, b);
}

/// The kind of the result of `tape` (an abstract run over the kinds of its registers).
Kind result_kind(const Tape& tape) {
  std::vector<Kind> kind(std::max<std::size_t>(tape.registers, Tape::kVariables), Kind::Other);
  for (std::uint32_t v = 0; v < Tape::kVariables; ++v) kind[v] = Kind::Affine;
  for (const expr::ConstantRegister& c : tape.constants) kind[c.reg] = Kind::Constant;
  for (const Instruction& in : tape.code) {
    const Kind a = kind[in.a];
    const Kind b = expr::is_binary(in.op) ? kind[in.b] : Kind::Constant;
    Kind out = Kind::Other;
    switch (in.op) {
      case Op::Neg:
      case Op::AddC:
      case Op::MulC:
      case Op::RSubC:
      case Op::DivC:
        out = a;
        break;
      case Op::Add:
      case Op::Sub:
        out = join(a, b);
        break;
      case Op::Mul:
        out = a == Kind::Constant ? b : (b == Kind::Constant ? a : Kind::Other);
        break;
      case Op::Div:
        out = b == Kind::Constant ? a : Kind::Other;
        break;
      default:
        out = join(a, b) == Kind::Constant ? Kind::Constant : Kind::Other;
        break;
    }
    kind[in.out] = out;
  }
  return kind[tape.result];
}

/// The same plane to `tolerance` (sum of the coefficients' differences).
bool same_plane(const HalfSpace& h, const HalfSpace& o, double tolerance) {
  return std::abs(o.a - h.a) + std::abs(o.b - h.b) + std::abs(o.c - h.c) + std::abs(o.d - h.d) < tolerance;
}

/// The walk down f's tree of max: every leaf as the branch choice that leads to it.
class LeafWalk {
 public:
  /// `split_negated_min`: a min under an odd number of decreasing steps is split too (-min(a, b) is
  /// max(-a, -b)), for the union of two solids read as the complement of their complements' intersection.
  explicit LeafWalk(const Tape& tape, bool split_negated_min = false)
      : tape_(tape),
        switches_(expr::switch_instructions(tape)),
        writers_(operand_writers(tape)),
        split_negated_min_(split_negated_min) {
    switch_of_.assign(tape.code.size(), -1);
    for (std::size_t s = 0; s < switches_.size(); ++s) switch_of_[switches_[s]] = static_cast<int>(s);
  }

  /// The leaves under f's root, or false when there are too many.
  bool run(std::vector<BranchChoice>& leaves) {
    leaves = collect(writers_.root, BranchChoice(switches_.size(), expr::kOpen));
    return !overflow_;
  }

  Kind leaf_kind(const BranchChoice& choice) const {
    return result_kind(expr::specialise(tape_, switches_, choice));
  }
  Tape leaf_tape(const BranchChoice& choice) const { return expr::specialise(tape_, switches_, choice); }

 private:
  static constexpr std::size_t kMostLeaves = 4 * kMaxCapPlanes;

  const Tape& tape_;
  std::vector<std::uint32_t> switches_;
  OperandWriters writers_;
  bool split_negated_min_ = false;
  std::vector<int> switch_of_;
  bool overflow_ = false;

  bool has_plane(const std::vector<BranchChoice>& leaves) const {
    return std::any_of(leaves.begin(), leaves.end(),
                       [this](const BranchChoice& c) { return leaf_kind(c) != Kind::Other; });
  }

  /// The leaves under `node`; `negated` when an odd number of decreasing steps lie above it (a max
  /// there is a min of the whole: one leaf, as is abs).
  std::vector<BranchChoice> collect(int node, const BranchChoice& choice, bool negated = false) {
    if (overflow_ || node < 0) return {choice};
    const Instruction& in = tape_.code[static_cast<std::size_t>(node)];
    const auto index = static_cast<std::size_t>(node);
    if (const int order = monotone_step(in))
      return collect(writers_.a[index], choice, negated != (order < 0));
    const bool splits = negated ? split_negated_min_ && in.op == Op::Min : in.op == Op::Max;
    if (negated && !splits) return {choice};
    if (in.op == Op::Abs) {
      // abs(u) = max(u, -u): two planes when u is affine, else one leaf.
      BranchChoice plus = choice, minus = choice;
      plus[static_cast<std::size_t>(switch_of_[index])] = 0;
      minus[static_cast<std::size_t>(switch_of_[index])] = 1;
      if (leaf_kind(plus) == Kind::Affine && leaf_kind(minus) == Kind::Affine) return {plus, minus};
      return {choice};
    }
    if (!splits) return {choice};
    std::vector<BranchChoice> out;
    for (std::int8_t side = 0; side < 2; ++side) {
      BranchChoice c = choice;
      c[static_cast<std::size_t>(switch_of_[index])] = side;
      std::vector<BranchChoice> leaves =
          collect(side == 0 ? writers_.a[index] : writers_.b[index], c, negated);
      // An operand with no plane under it is one smooth leaf, its own switches left open.
      if (!has_plane(leaves)) leaves = {c};
      out.insert(out.end(), leaves.begin(), leaves.end());
    }
    if (out.size() > kMostLeaves) overflow_ = true;
    return out;
  }
};

/// The same planes, in any order (to rounding).
bool same_planes(const ConvexRegion& a, const ConvexRegion& b) {
  if (a.size() != b.size()) return false;
  return std::all_of(a.begin(), a.end(), [&b](const HalfSpace& h) {
    return std::any_of(b.begin(), b.end(), [&h](const HalfSpace& o) { return same_plane(h, o, 1e-12); });
  });
}

}  // namespace

SurfacePtr union_complement(const Surface& f, const Box& box) {
  const Expression* formula = f.expression();
  if (formula == nullptr || formula->tape().code.empty()) return nullptr;
  const Tape& tape = formula->tape();
  const int node = root_node(tape, operand_writers(tape));
  if (node < 0 || tape.code[static_cast<std::size_t>(node)].op != Op::Min) return nullptr;
  // -step(min(a, b)) = max(-step(a), -step(b)) for an increasing step: the negated operands under a max,
  // which the readers of capped shapes split.
  const std::vector<std::uint32_t> switches = expr::switch_instructions(tape);
  return expression_surface(
      Expression(std::make_shared<const Tape>(combined(Op::Max, negated(with_branch(tape, switches, node, 0)),
                                                       negated(with_branch(tape, switches, node, 1))))),
      box, "the complement");
}

std::optional<ShelledShape> split_shelled_shape(const Surface& f, const Box& box) {
  const Expression* formula = f.expression();
  if (formula == nullptr || formula->tape().code.empty()) return std::nullopt;
  const Tape& tape = formula->tape();
  // The root through increasing steps to a min.
  const OperandWriters writers = operand_writers(tape);
  int node = writers.root;
  while (node >= 0 && monotone_step(tape.code[static_cast<std::size_t>(node)]) > 0)
    node = writers.a[static_cast<std::size_t>(node)];
  if (node < 0 || tape.code[static_cast<std::size_t>(node)].op != Op::Min) return std::nullopt;
  const std::vector<std::uint32_t> switches = expr::switch_instructions(tape);
  const auto s = static_cast<std::size_t>(
      std::find(switches.begin(), switches.end(), static_cast<std::uint32_t>(node)) - switches.begin());
  std::optional<CappedShape> side[2];
  for (std::int8_t k = 0; k < 2; ++k) {
    BranchChoice choice(switches.size(), expr::kOpen);
    choice[s] = k;
    const SurfacePtr operand_surface =
        expression_surface(Expression(std::make_shared<const Tape>(expr::specialise(tape, switches, choice))),
                           box, "an operand");
    side[k] = split_capped_shape(*operand_surface, box);
    if (!side[k] || !side[k]->smooth) return std::nullopt;
  }
  for (int lattice = 0; lattice < 2; ++lattice) {
    const CappedShape& part = *side[lattice];
    const CappedShape& skin = *side[1 - lattice];
    const Expression* lattice_formula = part.smooth->expression();
    const Expression* skin_formula = skin.smooth->expression();
    if (lattice_formula == nullptr || skin_formula == nullptr || !same_planes(part.planes, skin.planes))
      continue;
    // The skin's curved operand is minus a polyhedron: -R.
    const SurfacePtr inner_surface = expression_surface(
        Expression(std::make_shared<const Tape>(negated(skin_formula->tape()))), box, "the inner polyhedron");
    const std::optional<CappedShape> inner = split_capped_shape(*inner_surface, box);
    if (!inner || inner->smooth) continue;
    SurfacePtr hollow = expression_surface(
        Expression(std::make_shared<const Tape>(negated(lattice_formula->tape()))), box, "the hollows");
    return ShelledShape{std::move(hollow), part.planes, inner->planes};
  }
  return std::nullopt;
}

namespace {

/// f's leaves as max(c_1, ..., c_m, p_1, ..., p_k): the curved operands (formulas of their own) and the
/// planes (unit normals out of the solid, duplicates kept once); nullopt when f is not such a tree, a
/// leaf is a constant or more than kMaxCapPlanes planes.
std::optional<std::pair<std::vector<Expression>, ConvexRegion>> max_leaves(const Surface& f) {
  const Expression* formula = f.expression();
  if (formula == nullptr) return std::nullopt;
  const Tape& tape = formula->tape();
  if (tape.code.empty()) return std::nullopt;
  LeafWalk walk(tape);
  std::vector<BranchChoice> leaves;
  if (!walk.run(leaves) || leaves.size() < 2) return std::nullopt;
  std::vector<Expression> curved;
  ConvexRegion planes;
  for (const BranchChoice& leaf : leaves) {
    const Kind kind = walk.leaf_kind(leaf);
    Expression e(std::make_shared<const Tape>(walk.leaf_tape(leaf)));
    if (kind == Kind::Other) {
      curved.push_back(std::move(e));
      continue;
    }
    if (kind != Kind::Affine) return std::nullopt;  // a constant operand: no plane
    const ValueGradient at_origin = e.value_gradient(Vec3::Zero());
    const double length = at_origin.gradient.norm();
    if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(at_origin.value)) return std::nullopt;
    const Vec3 n = at_origin.gradient / length;
    const HalfSpace h{n.x(), n.y(), n.z(), at_origin.value / length};
    const bool repeated = std::any_of(planes.begin(), planes.end(),
                                      [&h](const HalfSpace& o) { return same_plane(h, o, 1e-14); });
    if (!repeated) planes.push_back(h);
  }
  if (planes.size() > kMaxCapPlanes) return std::nullopt;
  return std::make_pair(std::move(curved), std::move(planes));
}

}  // namespace

std::optional<CappedShape> split_capped_shape(const Surface& f, const Box& box) {
  std::optional<std::pair<std::vector<Expression>, ConvexRegion>> leaves = max_leaves(f);
  // Two curved operands: a crease between them, not a cap.
  if (!leaves || leaves->first.size() > 1 || leaves->second.empty()) return std::nullopt;
  SurfacePtr g = leaves->first.empty()
                     ? nullptr
                     : expression_surface(std::move(leaves->first.front()), box, "the smooth operand");
  return CappedShape{std::move(g), std::move(leaves->second)};
}

std::optional<CappedCutShape> split_capped_cut_shape(const Surface& f, const Box& box) {
  std::optional<std::pair<std::vector<Expression>, ConvexRegion>> leaves = max_leaves(f);
  if (!leaves || leaves->second.empty()) return std::nullopt;
  if (leaves->first.size() == 2)
    return CappedCutShape{
        CutShape{expression_surface(std::move(leaves->first[0]), box, "the first operand"),
                 expression_surface(std::move(leaves->first[1]), box, "the second operand")},
        std::move(leaves->second)};
  // max(max(a, b), planes): the operand with no plane under it is one leaf, itself two solids.
  if (leaves->first.size() != 1) return std::nullopt;
  const SurfacePtr both = expression_surface(std::move(leaves->first.front()), box, "the solids");
  std::optional<CutShape> solids = split_cut_shape(*both, box);
  if (!solids) return std::nullopt;
  return CappedCutShape{std::move(*solids), std::move(leaves->second)};
}

namespace {

/// The two curved leaves of `tape`'s tree of max (see LeafWalk), or nullopt.
std::optional<CutShape> two_curved_leaves(const Tape& tape, bool split_negated_min, const Box& box) {
  LeafWalk walk(tape, split_negated_min);
  std::vector<BranchChoice> leaves;
  if (!walk.run(leaves) || leaves.size() != 2) return std::nullopt;
  for (const BranchChoice& leaf : leaves)
    if (walk.leaf_kind(leaf) != Kind::Other) return std::nullopt;
  return CutShape{expression_surface(Expression(std::make_shared<const Tape>(walk.leaf_tape(leaves[0]))), box,
                                     "the first operand"),
                  expression_surface(Expression(std::make_shared<const Tape>(walk.leaf_tape(leaves[1]))), box,
                                     "the second operand"),
                  split_negated_min};
}

}  // namespace

std::optional<CutShape> split_cut_shape(const Surface& f, const Box& box) {
  const Expression* formula = f.expression();
  if (formula == nullptr || formula->tape().code.empty()) return std::nullopt;
  if (std::optional<CutShape> intersection = two_curved_leaves(formula->tape(), false, box))
    return intersection;
  // min(a, b) = -max(-a, -b): the leaves of -f with its min split are -a and -b.
  return two_curved_leaves(negated(formula->tape()), true, box);
}

}  // namespace isopatch
