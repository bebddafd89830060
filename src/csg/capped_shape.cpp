// A smooth solid capped by a convex polyhedron, read from its formula (capped_shape.hpp).
#include "csg/capped_shape.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

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

/// The walk down f's tree of max: every leaf as the branch choice that leads to it.
class LeafWalk {
 public:
  explicit LeafWalk(const Tape& tape) : tape_(tape), switches_(expr::switch_instructions(tape)) {
    switch_of_.assign(tape.code.size(), -1);
    for (std::size_t s = 0; s < switches_.size(); ++s) switch_of_[switches_[s]] = static_cast<int>(s);
    // The instruction each operand reads (the last to write its register before), -1 for x, y, z and
    // the constants.
    std::vector<int> writer(std::max<std::size_t>(tape.registers, Tape::kVariables), -1);
    def_a_.resize(tape.code.size());
    def_b_.resize(tape.code.size());
    for (std::size_t i = 0; i < tape.code.size(); ++i) {
      def_a_[i] = writer[tape.code[i].a];
      def_b_[i] = expr::is_binary(tape.code[i].op) ? writer[tape.code[i].b] : -1;
      writer[tape.code[i].out] = static_cast<int>(i);
    }
    root_ = writer[tape.result];
  }

  /// The leaves under f's root, or false when there are too many.
  bool run(std::vector<BranchChoice>& leaves) {
    leaves = collect(root_, BranchChoice(switches_.size(), expr::kOpen));
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
  std::vector<int> switch_of_, def_a_, def_b_;
  int root_ = -1;
  bool overflow_ = false;

  bool has_plane(const std::vector<BranchChoice>& leaves) const {
    return std::any_of(leaves.begin(), leaves.end(),
                       [this](const BranchChoice& c) { return leaf_kind(c) != Kind::Other; });
  }

  std::vector<BranchChoice> collect(int node, const BranchChoice& choice) {
    if (overflow_ || node < 0) return {choice};
    const Instruction& in = tape_.code[static_cast<std::size_t>(node)];
    const auto index = static_cast<std::size_t>(node);
    const bool increasing = in.op == Op::AddC || ((in.op == Op::MulC || in.op == Op::DivC) && in.imm > 0.0);
    if (increasing) return collect(def_a_[index], choice);
    if (in.op == Op::Abs) {
      // abs(u) = max(u, -u): two planes when u is affine, else one leaf.
      BranchChoice plus = choice, minus = choice;
      plus[static_cast<std::size_t>(switch_of_[index])] = 0;
      minus[static_cast<std::size_t>(switch_of_[index])] = 1;
      if (leaf_kind(plus) == Kind::Affine && leaf_kind(minus) == Kind::Affine) return {plus, minus};
      return {choice};
    }
    if (in.op != Op::Max) return {choice};
    std::vector<BranchChoice> out;
    for (std::int8_t side = 0; side < 2; ++side) {
      BranchChoice c = choice;
      c[static_cast<std::size_t>(switch_of_[index])] = side;
      std::vector<BranchChoice> leaves = collect(side == 0 ? def_a_[index] : def_b_[index], c);
      // An operand with no plane under it is one smooth leaf, its own switches left open.
      if (!has_plane(leaves)) leaves = {c};
      out.insert(out.end(), leaves.begin(), leaves.end());
    }
    if (out.size() > kMostLeaves) overflow_ = true;
    return out;
  }
};

}  // namespace

std::optional<CappedShape> split_capped_shape(const Surface& f, const Box& box) {
  const Expression* formula = f.expression();
  if (formula == nullptr) return std::nullopt;
  const Tape& tape = formula->tape();
  if (tape.code.empty()) return std::nullopt;
  LeafWalk walk(tape);
  std::vector<BranchChoice> leaves;
  if (!walk.run(leaves) || leaves.size() < 2) return std::nullopt;
  std::optional<Expression> smooth;
  ConvexRegion planes;
  for (const BranchChoice& leaf : leaves) {
    const Kind kind = walk.leaf_kind(leaf);
    Expression e(std::make_shared<const Tape>(walk.leaf_tape(leaf)));
    if (kind == Kind::Other) {
      if (smooth) return std::nullopt;  // two curved operands: a crease between them, not a cap
      smooth = std::move(e);
      continue;
    }
    if (kind != Kind::Affine) return std::nullopt;  // a constant operand: no plane
    const ValueGradient at_origin = e.value_gradient(Vec3::Zero());
    const double length = at_origin.gradient.norm();
    if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(at_origin.value)) return std::nullopt;
    const Vec3 n = at_origin.gradient / length;
    const HalfSpace h{n.x(), n.y(), n.z(), at_origin.value / length};
    const bool repeated = std::any_of(planes.begin(), planes.end(), [&h](const HalfSpace& o) {
      return std::abs(o.a - h.a) + std::abs(o.b - h.b) + std::abs(o.c - h.c) + std::abs(o.d - h.d) < 1e-14;
    });
    if (!repeated) planes.push_back(h);
  }
  if (planes.empty() || planes.size() > kMaxCapPlanes) return std::nullopt;
  SurfacePtr g = smooth ? expression_surface(std::move(*smooth), box, "the smooth operand") : nullptr;
  return CappedShape{std::move(g), std::move(planes)};
}

}  // namespace isopatch
