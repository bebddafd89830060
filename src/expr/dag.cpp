// Building the DAG (sharing, folding, rewrites) and lowering it to a tape.
//
// Rewrites are limited to ones that are exact in floating point, so a formula means the same before
// and after: x*1 = x, x/1 = x, x+0 = x (up to the sign of zero), x+x = 2*x, x*x = x^2, --x = x.
// Integer powers become multiplications: x^(2k) = (x^k)^2 and x^-n = 1/x^n, which lets x^4 reuse the
// x^2 of the same formula and keeps interval bounds tight (the square of an interval is exact).
#include "expr/dag.hpp"

#include "expr/scalar.hpp"

#include <bit>
#include <cassert>
#include <cmath>
#include <limits>

namespace isopatch::expr {
namespace {

constexpr long long kMaxIntegerPower = 1 << 20;

bool is_small_integer(double v) {
  return std::isfinite(v) && v == std::trunc(v) && std::fabs(v) <= static_cast<double>(kMaxIntegerPower);
}

}  // namespace

std::size_t Dag::KeyHash::operator()(const Key& k) const {
  std::uint64_t h = static_cast<std::uint64_t>(k.op);
  h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.a));
  h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.b));
  h = h * 0x9E3779B97F4A7C15ull ^ k.imm_bits;
  return static_cast<std::size_t>(h ^ (h >> 29));
}

NodeId Dag::make(Op op, NodeId a, NodeId b, double imm) {
  const Key key{op, a, b, std::bit_cast<std::uint64_t>(imm)};
  if (const auto it = index_.find(key); it != index_.end()) return it->second;
  const auto id = static_cast<NodeId>(nodes_.size());
  nodes_.push_back(Node{op, a, b, imm});
  index_.emplace(key, id);
  return id;
}

NodeId Dag::variable(int axis) {
  return make(Op::Var, -1, -1, static_cast<double>(axis));
}

NodeId Dag::constant(double value) {
  return make(Op::Const, -1, -1, value);
}

NodeId Dag::unary(Op op, NodeId a) {
  assert(!is_leaf(op) && !is_binary(op));
  const Node& n = node(a);
  if (n.op == Op::Const) return constant(apply_unary(op, n.imm, 0.0));
  if (op == Op::Neg && n.op == Op::Neg) return n.a;
  return make(op, a, -1, 0.0);
}

NodeId Dag::with_constant(Op op, NodeId a, double c) {
  if (is_constant(a)) return constant(apply_unary(op, node(a).imm, c));
  switch (op) {
    case Op::AddC:
      if (c == 0.0) return a;
      break;
    case Op::MulC:
      if (c == 1.0) return a;
      if (c == -1.0) return unary(Op::Neg, a);
      break;
    case Op::DivC:
      if (c == 1.0) return a;
      break;
    case Op::RSubC:
      if (c == 0.0) return unary(Op::Neg, a);
      break;
    default:
      break;
  }
  return make(op, a, -1, c);
}

NodeId Dag::integer_power(NodeId a, long long n) {
  if (n == 0) return constant(1.0);
  if (n == 1) return a;
  if (n < 0) return with_constant(Op::RDivC, integer_power(a, -n), 1.0);
  if (n % 2 == 0) {
    const NodeId half = integer_power(a, n / 2);
    if (is_constant(half)) return constant(apply_unary(Op::Square, node(half).imm, 0.0));
    return make(Op::Square, half, -1, 0.0);
  }
  return make(Op::Powi, a, -1, static_cast<double>(n));
}

NodeId Dag::power(NodeId a, NodeId b) {
  const Node& e = node(b);
  if (e.op != Op::Const) return make(Op::Pow, a, b, 0.0);
  if (e.imm == 0.0) return constant(1.0);  // std::pow(anything, 0) == 1, even NaN
  if (is_small_integer(e.imm)) return integer_power(a, static_cast<long long>(e.imm));
  return with_constant(Op::PowC, a, e.imm);
}

NodeId Dag::binary(Op op, NodeId a, NodeId b) {
  assert(is_binary(op));
  const bool ca = is_constant(a), cb = is_constant(b);
  if (ca && cb) return constant(apply_binary(op, node(a).imm, node(b).imm));
  switch (op) {
    case Op::Add:
      if (cb) return with_constant(Op::AddC, a, node(b).imm);
      if (ca) return with_constant(Op::AddC, b, node(a).imm);
      if (a == b) return with_constant(Op::MulC, a, 2.0);
      break;
    case Op::Sub:
      if (cb) return with_constant(Op::AddC, a, -node(b).imm);
      if (ca) return with_constant(Op::RSubC, b, node(a).imm);
      break;
    case Op::Mul:
      if (cb) return with_constant(Op::MulC, a, node(b).imm);
      if (ca) return with_constant(Op::MulC, b, node(a).imm);
      if (a == b) return make(Op::Square, a, -1, 0.0);
      break;
    case Op::Div:
      if (cb) return with_constant(Op::DivC, a, node(b).imm);
      if (ca) return with_constant(Op::RDivC, b, node(a).imm);
      break;
    case Op::Pow:
      return power(a, b);
    default:
      break;
  }
  if (is_commutative(op) && b < a) std::swap(a, b);
  return make(op, a, b, 0.0);
}

Tape Dag::lower(NodeId root) const {
  const std::size_t n = nodes_.size();
  // Children always precede parents (a node is made after its operands), so one backward sweep
  // marks what the root needs and records each value's last use.
  std::vector<char> needed(n, 0);
  std::vector<NodeId> last_use(n, -1);
  needed[static_cast<std::size_t>(root)] = 1;
  for (auto i = static_cast<NodeId>(n) - 1; i >= 0; --i) {
    const Node& nd = nodes_[static_cast<std::size_t>(i)];
    if (!needed[static_cast<std::size_t>(i)] || is_leaf(nd.op)) continue;
    for (const NodeId c : {nd.a, nd.b}) {
      if (c < 0) continue;
      needed[static_cast<std::size_t>(c)] = 1;
      last_use[static_cast<std::size_t>(c)] = std::max(last_use[static_cast<std::size_t>(c)], i);
    }
  }

  Tape tape;
  std::vector<std::uint32_t> reg(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!needed[i]) continue;
    if (nodes_[i].op == Op::Var) reg[i] = static_cast<std::uint32_t>(nodes_[i].imm);
    if (nodes_[i].op == Op::Const) {
      reg[i] = tape.registers++;
      tape.constants.push_back({reg[i], nodes_[i].imm});
    }
  }
  std::vector<std::uint32_t> free_registers;  // a stack: the most recently freed register is hot
  for (std::size_t i = 0; i < n; ++i) {
    const Node& nd = nodes_[i];
    if (!needed[i] || is_leaf(nd.op)) continue;
    if (free_registers.empty()) {
      reg[i] = tape.registers++;
    } else {
      reg[i] = free_registers.back();
      free_registers.pop_back();
    }
    const std::uint32_t ra = reg[static_cast<std::size_t>(nd.a)];
    const std::uint32_t rb = nd.b >= 0 ? reg[static_cast<std::size_t>(nd.b)] : ra;
    tape.code.push_back({nd.op, reg[i], ra, rb, nd.imm});
    // Free dead operands only after the output register was chosen: out never aliases an operand.
    for (const NodeId c : {nd.a, nd.b}) {
      if (c < 0 || is_leaf(nodes_[static_cast<std::size_t>(c)].op)) continue;
      if (last_use[static_cast<std::size_t>(c)] == static_cast<NodeId>(i) && !(c == nd.b && nd.a == nd.b))
        free_registers.push_back(reg[static_cast<std::size_t>(c)]);
    }
  }
  tape.result = reg[static_cast<std::size_t>(root)];
  return tape;
}

}  // namespace isopatch::expr
