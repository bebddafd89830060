#pragma once
// The meaning of every op on plain doubles. Constant folding, the point evaluator and (loop by loop)
// the batch evaluator all compute exactly these expressions, so a folded constant, a single point and
// a batch give bit-identical results, and the interval evaluator can mirror them (interval_math.hpp).

#include "expr/op.hpp"

#include <cmath>

namespace isopatch::expr {

/// pow and hypot with NaN from either argument propagating. IEEE makes pow(1, NaN) = 1 and
/// hypot(inf, NaN) = inf; f would then be finite at a point where part of it is undefined, while the
/// interval extension (sound over the defined points only) says nothing there.
/// pow of a negative base is defined for finite integer exponents only (IEEE gives pow(-inf, -5.5) = 0
/// and pow(-0.5, inf) = 0; the interval extension leaves such points out).
inline double strict_pow(double a, double b) {
  if (a != a || b != b) return a + b;
  if (a < 0.0 && (b != std::trunc(b) || !std::isfinite(b))) return std::nan("");
  return std::pow(a, b);
}
inline double strict_hypot(double a, double b) {
  return (a != a || b != b) ? a + b : std::hypot(a, b);
}

/// x^n for n >= 0 by repeated squaring (x^2 = x*x, x^3 = x*(x*x), x^4 = (x*x)*(x*x), ...).
inline double ipow(double x, unsigned n) {
  double r = 1.0;
  while (n != 0) {
    if (n & 1u) r *= x;
    n >>= 1u;
    if (n != 0) x *= x;
  }
  return r;
}

/// op applied to a (and b for binary ops; c is the instruction's constant).
inline double apply(Op op, double a, double b, double c) {
  switch (op) {
    case Op::Var:
    case Op::Const:
      return c;
    case Op::Neg:
      return -a;
    case Op::Square:
      return a * a;
    case Op::Powi:
      return ipow(a, static_cast<unsigned>(c));
    case Op::PowC:
      return strict_pow(a, c);
    case Op::AddC:
      return a + c;
    case Op::MulC:
      return a * c;
    case Op::RSubC:
      return c - a;
    case Op::DivC:
      return a / c;
    case Op::RDivC:
      return c / a;
    case Op::Sqrt:
      return std::sqrt(a);
    case Op::Exp:
      return std::exp(a);
    case Op::Log:
      return std::log(a);
    case Op::Sin:
      return std::sin(a);
    case Op::Cos:
      return std::cos(a);
    case Op::Tan:
      return std::tan(a);
    case Op::Asin:
      return std::asin(a);
    case Op::Acos:
      return std::acos(a);
    case Op::Atan:
      return std::atan(a);
    case Op::Sinh:
      return std::sinh(a);
    case Op::Cosh:
      return std::cosh(a);
    case Op::Tanh:
      return std::tanh(a);
    case Op::Abs:
      return std::fabs(a);
    case Op::Add:
      return a + b;
    case Op::Sub:
      return a - b;
    case Op::Mul:
      return a * b;
    case Op::Div:
      return a / b;
    case Op::Pow:
      return strict_pow(a, b);
    case Op::Atan2:
      return std::atan2(a, b);
    case Op::Hypot:
      return strict_hypot(a, b);
    // min and max propagate NaN from either side (f is undefined where any part of it is), so point,
    // batch and interval evaluation agree on where f is defined.
    case Op::Min:
      return (b < a || b != b) ? b : a;
    case Op::Max:
      return (a < b || b != b) ? b : a;
  }
  return std::nan("");
}

inline double apply_unary(Op op, double a, double c) {
  return apply(op, a, 0.0, c);
}
inline double apply_binary(Op op, double a, double b) {
  return apply(op, a, b, 0.0);
}

}  // namespace isopatch::expr
