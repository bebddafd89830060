// Single-point evaluators: value, value with gradient (first-order forward mode) and value with
// gradient and Hessian (second-order forward mode), the registers the library's jets (autodiff.hpp:
// GradientJet and Jet) with the chain rule written out per instruction. A switch per instruction and
// registers on the stack (or, for long tapes, in a thread-local buffer): no allocation, no virtual
// call.
#include <isopatch/autodiff.hpp>

#include "expr/derivatives.hpp"
#include "expr/evaluate.hpp"
#include "expr/scalar.hpp"

#include <array>
#include <cstddef>
#include <new>
#include <type_traits>
#include <vector>

namespace isopatch::expr {
namespace {

/// Runs f(registers) with at least `count` registers of type T. The stack registers are left
/// uninitialized (every register is written before it is read: the variables and constants first, then
/// each instruction's output), so a short tape pays nothing for them.
template <class T, std::size_t N, class F>
auto with_registers(std::size_t count, F&& f) {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);
  if (count <= N) {
    alignas(T) std::byte storage[N * sizeof(T)];  // implicitly creates the T objects (trivial types)
    return f(std::launder(reinterpret_cast<T*>(storage)));
  }
  thread_local std::vector<T> heap;
  if (heap.size() < count) heap.resize(count);
  return f(heap.data());
}

constexpr int kPairI[6] = {0, 0, 0, 1, 1, 2};
constexpr int kPairJ[6] = {0, 1, 2, 1, 2, 2};

double run_value(const Tape& t, double* r, const Vec3& p) {
  r[0] = p.x();
  r[1] = p.y();
  r[2] = p.z();
  for (const ConstantRegister& c : t.constants) r[c.reg] = c.value;
  for (const Instruction& in : t.code) r[in.out] = apply(in.op, r[in.a], r[in.b], in.imm);
  return r[t.result];
}

ValueGradient run_gradient(const Tape& t, GradientJet* r, const Vec3& p) {
  for (int k = 0; k < 3; ++k) {
    r[k].v = p[k];
    r[k].g = {0.0, 0.0, 0.0};
    r[k].g[static_cast<std::size_t>(k)] = 1.0;
  }
  for (const ConstantRegister& c : t.constants) r[c.reg] = GradientJet(c.value);
  for (const Instruction& in : t.code) {
    const GradientJet& a = r[in.a];
    const GradientJet& b = r[in.b];
    GradientJet& o = r[in.out];
    switch (in.op) {
      case Op::Add:
        o.v = a.v + b.v;
        for (int k = 0; k < 3; ++k) o.g[k] = a.g[k] + b.g[k];
        break;
      case Op::Sub:
        o.v = a.v - b.v;
        for (int k = 0; k < 3; ++k) o.g[k] = a.g[k] - b.g[k];
        break;
      case Op::Min:  // NaN from either side propagates, as in scalar.hpp
        o = (b.v < a.v || b.v != b.v) ? b : a;
        break;
      case Op::Max:
        o = (a.v < b.v || b.v != b.v) ? b : a;
        break;
      // The cheap ops of polynomials inline; each is binary_/unary_derivatives written out.
      case Op::Mul:
        o.v = a.v * b.v;
        for (int k = 0; k < 3; ++k) o.g[k] = b.v * a.g[k] + a.v * b.g[k];
        break;
      case Op::Square:
        o.v = a.v * a.v;
        for (int k = 0; k < 3; ++k) o.g[k] = (2.0 * a.v) * a.g[k];
        break;
      case Op::AddC:
        o.v = a.v + in.imm;
        o.g = a.g;
        break;
      case Op::MulC:
        o.v = a.v * in.imm;
        for (int k = 0; k < 3; ++k) o.g[k] = in.imm * a.g[k];
        break;
      case Op::Neg:
      case Op::RSubC:
        o.v = in.op == Op::Neg ? -a.v : in.imm - a.v;
        for (int k = 0; k < 3; ++k) o.g[k] = -a.g[k];
        break;
      case Op::Div:
      case Op::Pow:
      case Op::Atan2:
      case Op::Hypot: {
        const BinaryDerivatives d = binary_derivatives(in.op, a.v, b.v);
        o.v = d.f;
        for (int k = 0; k < 3; ++k) o.g[k] = d.fa * a.g[k] + d.fb * b.g[k];
        break;
      }
      default: {
        const UnaryDerivatives d = unary_derivatives(in.op, a.v, in.imm);
        o.v = d.v;
        for (int k = 0; k < 3; ++k) o.g[k] = d.d1 * a.g[k];
      }
    }
  }
  const GradientJet& f = r[t.result];
  return {f.v, Vec3(f.g[0], f.g[1], f.g[2])};
}

SecondOrder run_second_order(const Tape& t, Jet* r, const Vec3& p) {
  for (int k = 0; k < 3; ++k) {
    r[k] = Jet(p[k]);
    r[k].g[static_cast<std::size_t>(k)] = 1.0;
  }
  for (const ConstantRegister& c : t.constants) r[c.reg] = Jet(c.value);
  for (const Instruction& in : t.code) {
    const Jet& a = r[in.a];
    const Jet& b = r[in.b];
    Jet& o = r[in.out];
    switch (in.op) {
      case Op::Add:
      case Op::Sub: {
        const double s = in.op == Op::Add ? 1.0 : -1.0;
        o.v = in.op == Op::Add ? a.v + b.v : a.v - b.v;
        for (int k = 0; k < 3; ++k) o.g[k] = a.g[k] + s * b.g[k];
        for (int k = 0; k < 6; ++k) o.h[k] = a.h[k] + s * b.h[k];
        break;
      }
      case Op::Min:  // NaN from either side propagates, as in scalar.hpp
        o = (b.v < a.v || b.v != b.v) ? b : a;
        break;
      case Op::Max:
        o = (a.v < b.v || b.v != b.v) ? b : a;
        break;
      case Op::Mul:
      case Op::Div:
      case Op::Pow:
      case Op::Atan2:
      case Op::Hypot: {
        const BinaryDerivatives d = binary_derivatives(in.op, a.v, b.v);
        Jet res;
        res.v = d.f;
        for (int k = 0; k < 3; ++k) res.g[k] = d.fa * a.g[k] + d.fb * b.g[k];
        for (int k = 0; k < 6; ++k) {
          const int i = kPairI[k], j = kPairJ[k];
          res.h[k] = d.fa * a.h[k] + d.fb * b.h[k] + d.faa * a.g[i] * a.g[j] +
                     d.fab * (a.g[i] * b.g[j] + a.g[j] * b.g[i]) + d.fbb * b.g[i] * b.g[j];
        }
        o = res;
        break;
      }
      default: {
        const UnaryDerivatives d = unary_derivatives(in.op, a.v, in.imm);
        Jet res;
        res.v = d.v;
        for (int k = 0; k < 3; ++k) res.g[k] = d.d1 * a.g[k];
        for (int k = 0; k < 6; ++k) res.h[k] = d.d1 * a.h[k] + d.d2 * a.g[kPairI[k]] * a.g[kPairJ[k]];
        o = res;
      }
    }
  }
  const Jet& f = r[t.result];
  SecondOrder s;
  s.value = f.v;
  s.gradient = Vec3(f.g[0], f.g[1], f.g[2]);
  s.hessian << f.h[0], f.h[1], f.h[2], f.h[1], f.h[3], f.h[4], f.h[2], f.h[4], f.h[5];
  return s;
}

}  // namespace

double evaluate(const Tape& tape, const Vec3& p) {
  return with_registers<double, 128>(tape.registers, [&](double* r) { return run_value(tape, r, p); });
}

ValueGradient evaluate_gradient(const Tape& tape, const Vec3& p) {
  return with_registers<GradientJet, 64>(tape.registers,
                                         [&](GradientJet* r) { return run_gradient(tape, r, p); });
}

SecondOrder evaluate_second_order(const Tape& tape, const Vec3& p) {
  return with_registers<Jet, 32>(tape.registers, [&](Jet* r) { return run_second_order(tape, r, p); });
}

}  // namespace isopatch::expr
