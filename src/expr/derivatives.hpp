#pragma once
// First and second derivatives of every op at a point, for forward-mode differentiation. The
// expressions are written so that the interval gradient (eval_interval.cpp) can repeat them
// operation for operation on intervals, which makes its enclosure hold the computed derivatives.

#include "expr/op.hpp"
#include "expr/scalar.hpp"

#include <cmath>

namespace isopatch::expr {

/// v = phi(a), d1 = phi'(a), d2 = phi''(a) for a unary op (c: the instruction's constant).
struct UnaryDerivatives {
  double v, d1, d2;
};

inline UnaryDerivatives unary_derivatives(Op op, double a, double c) {
  switch (op) {
    case Op::Neg:
      return {-a, -1.0, 0.0};
    case Op::Square:
      return {a * a, 2.0 * a, 2.0};
    case Op::Powi: {
      const auto n = static_cast<unsigned>(c);
      return {ipow(a, n), c * ipow(a, n - 1), c * (c - 1.0) * ipow(a, n - 2)};
    }
    case Op::PowC:
      return {strict_pow(a, c), c * std::pow(a, c - 1.0), c * (c - 1.0) * std::pow(a, c - 2.0)};
    case Op::AddC:
      return {a + c, 1.0, 0.0};
    case Op::MulC:
      return {a * c, c, 0.0};
    case Op::RSubC:
      return {c - a, -1.0, 0.0};
    case Op::DivC:
      return {a / c, 1.0 / c, 0.0};
    case Op::RDivC: {
      const double v = c / a, inv = 1.0 / a, d1 = -(v * inv);
      return {v, d1, -2.0 * d1 * inv};
    }
    case Op::Sqrt: {
      const double s = std::sqrt(a), d1 = 0.5 / s;
      return {s, d1, -0.5 * d1 / a};
    }
    case Op::Exp: {
      const double e = std::exp(a);
      return {e, e, e};
    }
    case Op::Log: {
      const double d1 = 1.0 / a;
      return {std::log(a), d1, -(d1 * d1)};
    }
    case Op::Sin: {
      const double s = std::sin(a);
      return {s, std::cos(a), -s};
    }
    case Op::Cos: {
      const double co = std::cos(a);
      return {co, -std::sin(a), -co};
    }
    case Op::Tan: {
      const double t = std::tan(a), d1 = 1.0 + t * t;
      return {t, d1, 2.0 * t * d1};
    }
    case Op::Asin:
    case Op::Acos: {
      const double q = 1.0 - a * a, r = std::sqrt(q);
      const double d1 = op == Op::Asin ? 1.0 / r : -(1.0 / r);
      return {op == Op::Asin ? std::asin(a) : std::acos(a), d1, a * d1 / q};
    }
    case Op::Atan: {
      const double d1 = 1.0 / (1.0 + a * a);
      return {std::atan(a), d1, -2.0 * a * d1 * d1};
    }
    case Op::Sinh: {
      const double s = std::sinh(a);
      return {s, std::cosh(a), s};
    }
    case Op::Cosh: {
      const double ch = std::cosh(a);
      return {ch, std::sinh(a), ch};
    }
    case Op::Tanh: {
      const double t = std::tanh(a), d1 = 1.0 - t * t;
      return {t, d1, -2.0 * t * d1};
    }
    case Op::Abs:
      return {std::fabs(a), a < 0.0 ? -1.0 : 1.0, 0.0};
    default:
      return {std::nan(""), std::nan(""), std::nan("")};
  }
}

/// f(a, b) and its partial derivatives for a binary op other than Add, Sub, Min and Max (which the
/// evaluators handle directly).
struct BinaryDerivatives {
  double f, fa, fb, faa, fab, fbb;
};

inline BinaryDerivatives binary_derivatives(Op op, double a, double b) {
  switch (op) {
    case Op::Mul:
      return {a * b, b, a, 0.0, 1.0, 0.0};
    case Op::Div: {
      const double f = a / b, inv = 1.0 / b, fb = -(f * inv);
      return {f, inv, fb, 0.0, -(inv * inv), -2.0 * fb * inv};
    }
    case Op::Pow: {
      const double f = strict_pow(a, b), la = std::log(a), pm1 = std::pow(a, b - 1.0);
      const double fb = f * la;
      return {f, b * pm1, fb, b * (b - 1.0) * std::pow(a, b - 2.0), pm1 * (1.0 + b * la), fb * la};
    }
    case Op::Atan2: {  // a = y, b = x
      const double r2 = a * a + b * b, r4 = r2 * r2;
      const double faa = -2.0 * a * b / r4;
      return {std::atan2(a, b), b / r2, -(a / r2), faa, (a * a - b * b) / r4, -faa};
    }
    case Op::Hypot: {
      const double h = strict_hypot(a, b), h3 = h * h * h;
      return {h, a / h, b / h, b * b / h3, -(a * b) / h3, a * a / h3};
    }
    default:
      return {std::nan(""), 0.0, 0.0, 0.0, 0.0, 0.0};
  }
}

}  // namespace isopatch::expr
