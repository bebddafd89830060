#pragma once
// The expression DAG the parser builds: hash-consed nodes (an identical node is created once, so
// common subexpressions are shared), constant folding and a few exact rewrites applied as nodes are
// made, and lowering of the part reachable from the result to a Tape with register allocation.

#include "expr/op.hpp"
#include "expr/tape.hpp"

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace isopatch::expr {

using NodeId = std::int32_t;

struct Node {
  Op op;
  NodeId a = -1;
  NodeId b = -1;
  double imm = 0.0;
};

class Dag {
 public:
  NodeId variable(int axis);
  NodeId constant(double value);
  /// op(a) for a unary function op (Neg, Sqrt, Sin, ...; not the *C forms).
  NodeId unary(Op op, NodeId a);
  /// op(a, b) for a binary op (Add, Sub, Mul, Div, Pow, Atan2, Hypot, Min, Max).
  NodeId binary(Op op, NodeId a, NodeId b);

  bool is_constant(NodeId id) const { return nodes_[static_cast<std::size_t>(id)].op == Op::Const; }
  const Node& node(NodeId id) const { return nodes_[static_cast<std::size_t>(id)]; }
  std::size_t size() const { return nodes_.size(); }

  /// The tape computing node `root`; nodes `root` does not depend on are left out.
  Tape lower(NodeId root) const;

 private:
  struct Key {
    Op op;
    NodeId a, b;
    std::uint64_t imm_bits;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };

  NodeId make(Op op, NodeId a, NodeId b, double imm);
  NodeId with_constant(Op op, NodeId a, double c);  // the *C forms, with their identities
  NodeId integer_power(NodeId a, long long n);
  NodeId power(NodeId a, NodeId b);

  std::vector<Node> nodes_;
  std::unordered_map<Key, NodeId, KeyHash> index_;
};

}  // namespace isopatch::expr
