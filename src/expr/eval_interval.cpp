// Interval evaluators: an enclosure of f over a box, and of f with its gradient (forward mode on
// intervals). Each instruction repeats on intervals the very operations the point evaluators do
// (scalar.hpp, derivatives.hpp), so by the guarantee of interval_math.hpp the enclosures hold the
// computed point values, not only the exact ones.
#include "expr/evaluate.hpp"

#include <isopatch/interval_math.hpp>

#include <array>
#include <vector>

namespace isopatch::expr {
namespace {

Interval point(double v) {
  return {v, v};
}

Interval apply_interval(Op op, const Interval& a, const Interval& b, double c) {
  switch (op) {
    case Op::Var:
    case Op::Const:
      return point(c);
    case Op::Neg:
      return -a;
    case Op::Square:
      return sqr(a);
    case Op::Powi:
      return powi(a, static_cast<int>(c));
    case Op::PowC:
      return pow(a, c);
    case Op::AddC:  // x + 0 is exact: the copies specialise() makes of a switch's branch stay exact
      return c == 0.0 ? a : a + point(c);
    case Op::MulC:
      return a * point(c);
    case Op::RSubC:
      return point(c) - a;
    case Op::DivC:
      return a / point(c);
    case Op::RDivC:
      return point(c) / a;
    case Op::Sqrt:
      return sqrt(a);
    case Op::Exp:
      return exp(a);
    case Op::Log:
      return log(a);
    case Op::Sin:
      return sin(a);
    case Op::Cos:
      return cos(a);
    case Op::Tan:
      return tan(a);
    case Op::Asin:
      return asin(a);
    case Op::Acos:
      return acos(a);
    case Op::Atan:
      return atan(a);
    case Op::Sinh:
      return sinh(a);
    case Op::Cosh:
      return cosh(a);
    case Op::Tanh:
      return tanh(a);
    case Op::Abs:
      return abs(a);
    case Op::Add:
      return a + b;
    case Op::Sub:
      return a - b;
    case Op::Mul:
      return a * b;
    case Op::Div:
      return a / b;
    case Op::Pow:
      return pow(a, b);
    case Op::Atan2:
      return atan2(a, b);
    case Op::Hypot:
      return hypot(a, b);
    case Op::Min:
      return min(a, b);
    case Op::Max:
      return max(a, b);
  }
  return entire_interval();
}

/// Enclosure of phi'(a) for a unary op, mirroring unary_derivatives().d1.
Interval unary_slope(Op op, const Interval& a, double c) {
  const Interval one = point(1.0);
  switch (op) {
    case Op::Neg:
      return point(-1.0);
    case Op::Square:
      return point(2.0) * a;
    case Op::Powi:
      return point(c) * powi(a, static_cast<int>(c) - 1);
    case Op::PowC:
      return point(c) * pow(a, c - 1.0);
    case Op::AddC:
      return one;
    case Op::MulC:
      return point(c);
    case Op::RSubC:
      return point(-1.0);
    case Op::DivC:
      return point(1.0 / c);
    case Op::RDivC:
      return -((point(c) / a) * (one / a));
    case Op::Sqrt:
      return point(0.5) / sqrt(a);
    case Op::Exp:
      return exp(a);
    case Op::Log:
      return one / a;
    case Op::Sin:
      return cos(a);
    case Op::Cos:
      return -sin(a);
    case Op::Tan:
      return one + sqr(tan(a));
    case Op::Asin:
      return one / sqrt(one - sqr(a));
    case Op::Acos:
      return -(one / sqrt(one - sqr(a)));
    case Op::Atan:
      return one / (one + sqr(a));
    case Op::Sinh:
      return cosh(a);
    case Op::Cosh:
      return sinh(a);
    case Op::Tanh:
      return one - sqr(tanh(a));
    case Op::Abs:
      if (a.hi < 0.0) return point(-1.0);
      if (a.lo >= 0.0) return one;
      return {-1.0, 1.0};
    default:
      return entire_interval();
  }
}

struct IntervalJet {
  Interval v;
  std::array<Interval, 3> g;
};

/// Partial derivatives (fa, fb) of a binary op, mirroring binary_derivatives().
std::array<Interval, 2> binary_slopes(Op op, const Interval& a, const Interval& b) {
  const Interval one = point(1.0);
  switch (op) {
    case Op::Mul:
      return {b, a};
    case Op::Div: {
      const Interval inv = one / b;
      return {inv, -((a / b) * inv)};
    }
    case Op::Pow:
      return {b * pow(a, b - one), pow(a, b) * log(a)};
    case Op::Atan2: {
      const Interval r2 = sqr(a) + sqr(b);
      return {b / r2, -(a / r2)};
    }
    case Op::Hypot: {
      const Interval h = hypot(a, b);
      return {a / h, b / h};
    }
    default:
      return {entire_interval(), entire_interval()};
  }
}

IntervalJet select(const IntervalJet& a, const IntervalJet& b, bool take_a, bool take_b, const Interval& v) {
  IntervalJet r{v, {}};
  for (std::size_t k = 0; k < 3; ++k)
    r.g[k] = take_a && take_b ? hull(a.g[k], b.g[k]) : (take_a ? a.g[k] : b.g[k]);
  return r;
}

IntervalJet step(const Instruction& in, const IntervalJet& a, const IntervalJet& b) {
  IntervalJet r;
  switch (in.op) {
    case Op::Add:
    case Op::Sub:
      r.v = apply_interval(in.op, a.v, b.v, 0.0);
      for (std::size_t k = 0; k < 3; ++k) r.g[k] = in.op == Op::Add ? a.g[k] + b.g[k] : a.g[k] - b.g[k];
      return r;
    case Op::Min:  // picks b where b < a
      return select(a, b, !(b.v.hi < a.v.lo), b.v.lo < a.v.hi, min(a.v, b.v));
    case Op::Max:  // picks b where a < b
      return select(a, b, !(a.v.hi < b.v.lo), a.v.lo < b.v.hi, max(a.v, b.v));
    case Op::Mul:
    case Op::Div:
    case Op::Pow:
    case Op::Atan2:
    case Op::Hypot: {
      r.v = apply_interval(in.op, a.v, b.v, 0.0);
      const auto [fa, fb] = binary_slopes(in.op, a.v, b.v);
      for (std::size_t k = 0; k < 3; ++k) r.g[k] = fa * a.g[k] + fb * b.g[k];
      return r;
    }
    default: {
      r.v = apply_interval(in.op, a.v, b.v, in.imm);
      const Interval d1 = unary_slope(in.op, a.v, in.imm);
      for (std::size_t k = 0; k < 3; ++k) r.g[k] = d1 * a.g[k];
      return r;
    }
  }
}

template <class T>
T* thread_registers(std::size_t count) {
  thread_local std::vector<T> storage;
  if (storage.size() < count) storage.resize(count);
  return storage.data();
}

}  // namespace

Interval evaluate_interval(const Tape& tape, const Box& box) {
  Interval* r = thread_registers<Interval>(tape.registers);
  for (int k = 0; k < 3; ++k) r[k] = {box.lo[k], box.hi[k]};
  for (const ConstantRegister& c : tape.constants) r[c.reg] = point(c.value);
  for (const Instruction& in : tape.code) r[in.out] = apply_interval(in.op, r[in.a], r[in.b], in.imm);
  return r[tape.result];
}

IntervalGradient evaluate_interval_gradient(const Tape& tape, const Box& box) {
  IntervalJet* r = thread_registers<IntervalJet>(tape.registers);
  for (int k = 0; k < 3; ++k) {
    r[k].v = {box.lo[k], box.hi[k]};
    for (int j = 0; j < 3; ++j) r[k].g[static_cast<std::size_t>(j)] = point(j == k ? 1.0 : 0.0);
  }
  for (const ConstantRegister& c : tape.constants)
    r[c.reg] = {point(c.value), {point(0.0), point(0.0), point(0.0)}};
  for (const Instruction& in : tape.code) r[in.out] = step(in, r[in.a], r[in.b]);
  return {r[tape.result].v, r[tape.result].g};
}

Interval evaluate_interval_branches(const Tape& tape, const Box& box, std::vector<std::int8_t>& decided) {
  decided.assign(tape.code.size(), -1);
  Interval* r = thread_registers<Interval>(tape.registers);
  for (int k = 0; k < 3; ++k) r[k] = {box.lo[k], box.hi[k]};
  for (const ConstantRegister& c : tape.constants) r[c.reg] = point(c.value);
  for (std::size_t i = 0; i < tape.code.size(); ++i) {
    const Instruction& in = tape.code[i];
    const Interval a = r[in.a], b = r[in.b];
    // The point evaluators' branches (scalar.hpp): min takes b where b < a, max takes b where a < b,
    // abs negates where a < 0; a tie takes operand a.
    std::int8_t& d = decided[i];
    if (in.op == Op::Min) d = a.hi <= b.lo ? 0 : (b.hi < a.lo ? 1 : -1);
    if (in.op == Op::Max) d = b.hi <= a.lo ? 0 : (a.hi < b.lo ? 1 : -1);
    if (in.op == Op::Abs) d = a.lo >= 0.0 ? 0 : (a.hi < 0.0 ? 1 : -1);
    r[in.out] = apply_interval(in.op, a, b, in.imm);
  }
  return r[tape.result];
}

}  // namespace isopatch::expr
