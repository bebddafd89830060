// Interval enclosures of f, its gradient and its Hessian over a box: second-order forward mode on
// intervals, instruction by instruction as run_second_order() of eval_point.cpp does it on numbers
// (the second derivatives of derivatives.hpp written on intervals). Each factor of the chain rule is
// enclosed over the box, so the result holds the exact Hessian at every point of the box where f is
// twice differentiable. Where the gradient may jump inside the box (min and max taking either side,
// abs across 0) the Hessian is the whole line: there is no Hessian to bound, and a mean value form of
// the gradient must not be used.
#include "expr/evaluate.hpp"

#include <isopatch/interval_math.hpp>

#include <array>
#include <vector>

namespace isopatch::expr {
namespace {

constexpr std::array<int, 6> kHessianRow = {0, 0, 0, 1, 1, 2};
constexpr std::array<int, 6> kHessianColumn = {0, 1, 2, 1, 2, 2};

Interval exact_interval(double v) {
  return {v, v};
}

struct IntervalJet2 {
  Interval v;
  std::array<Interval, 3> g;
  std::array<Interval, 6> h;  // xx, xy, xz, yy, yz, zz
};

/// phi(a), phi'(a) and phi''(a) over `a` for a unary op (c: the instruction's constant).
struct UnaryEnclosure {
  Interval v, d1, d2;
};

UnaryEnclosure unary_enclosure(Op op, const Interval& a, double c) {
  const Interval one = exact_interval(1.0), zero = exact_interval(0.0);
  switch (op) {
    case Op::Neg:
      return {-a, exact_interval(-1.0), zero};
    case Op::Square:
      return {sqr(a), exact_interval(2.0) * a, exact_interval(2.0)};
    case Op::Powi: {
      const int n = static_cast<int>(c);
      const Interval d2 = n == 0 || n == 1 ? zero : exact_interval(c * (c - 1.0)) * powi(a, n - 2);
      return {powi(a, n), n == 0 ? zero : exact_interval(c) * powi(a, n - 1), d2};
    }
    case Op::PowC: {
      const Interval d2 = c == 0.0 || c == 1.0 ? zero : exact_interval(c * (c - 1.0)) * pow(a, c - 2.0);
      return {pow(a, c), c == 0.0 ? zero : exact_interval(c) * pow(a, c - 1.0), d2};
    }
    case Op::AddC:  // x + 0 is exact (the copies specialise() makes)
      return {c == 0.0 ? a : a + exact_interval(c), one, zero};
    case Op::MulC:
      return {a * exact_interval(c), exact_interval(c), zero};
    case Op::RSubC:
      return {exact_interval(c) - a, exact_interval(-1.0), zero};
    case Op::DivC:
      return {a / exact_interval(c), exact_interval(1.0 / c), zero};
    case Op::RDivC: {
      const Interval inv = one / a;
      return {exact_interval(c) / a, -(exact_interval(c) * sqr(inv)), exact_interval(2.0 * c) * powi(a, -3)};
    }
    case Op::Sqrt: {
      const Interval s = sqrt(a);
      return {s, exact_interval(0.5) / s, exact_interval(-0.25) / (a * s)};
    }
    case Op::Exp: {
      const Interval e = exp(a);
      return {e, e, e};
    }
    case Op::Log: {
      const Interval inv = one / a;
      return {log(a), inv, -sqr(inv)};
    }
    case Op::Sin: {
      const Interval s = sin(a);
      return {s, cos(a), -s};
    }
    case Op::Cos: {
      const Interval co = cos(a);
      return {co, -sin(a), -co};
    }
    case Op::Tan: {
      const Interval t = tan(a), d1 = one + sqr(t);
      return {t, d1, exact_interval(2.0) * t * d1};
    }
    case Op::Asin:
    case Op::Acos: {
      const Interval q = one - sqr(a), r = sqrt(q);
      const Interval d1 = op == Op::Asin ? one / r : -(one / r);
      return {op == Op::Asin ? asin(a) : acos(a), d1, a * d1 / q};
    }
    case Op::Atan: {
      const Interval d1 = one / (one + sqr(a));
      return {atan(a), d1, exact_interval(-2.0) * a * sqr(d1)};
    }
    case Op::Sinh: {
      const Interval s = sinh(a);
      return {s, cosh(a), s};
    }
    case Op::Cosh: {
      const Interval ch = cosh(a);
      return {ch, sinh(a), ch};
    }
    case Op::Tanh: {
      const Interval t = tanh(a), d1 = one - sqr(t);
      return {t, d1, exact_interval(-2.0) * t * d1};
    }
    case Op::Abs:
      if (a.hi < 0.0) return {abs(a), exact_interval(-1.0), zero};
      if (a.lo > 0.0) return {abs(a), one, zero};
      return {abs(a), {-1.0, 1.0}, entire_interval()};  // a kink inside
    default:
      return {entire_interval(), entire_interval(), entire_interval()};
  }
}

/// f(a, b) and its first and second partial derivatives over the boxes `a`, `b` (binary ops other than
/// Add, Sub, Min and Max).
struct BinaryEnclosure {
  Interval f, fa, fb, faa, fab, fbb;
};

BinaryEnclosure binary_enclosure(Op op, const Interval& a, const Interval& b) {
  const Interval one = exact_interval(1.0), zero = exact_interval(0.0);
  switch (op) {
    case Op::Mul:
      return {a * b, b, a, zero, one, zero};
    case Op::Div: {
      const Interval inv = one / b, f = a / b, fb = -(f * inv);
      return {f, inv, fb, zero, -sqr(inv), exact_interval(-2.0) * fb * inv};
    }
    case Op::Pow: {
      const Interval f = pow(a, b), la = log(a), pm1 = pow(a, b - one), fb = f * la;
      return {f, b * pm1, fb, b * (b - one) * pow(a, b - exact_interval(2.0)), pm1 * (one + b * la), fb * la};
    }
    case Op::Atan2: {  // a = y, b = x
      const Interval r2 = sqr(a) + sqr(b), r4 = sqr(r2);
      const Interval faa = exact_interval(-2.0) * a * b / r4;
      return {atan2(a, b), b / r2, -(a / r2), faa, (sqr(a) - sqr(b)) / r4, -faa};
    }
    case Op::Hypot: {
      const Interval h = hypot(a, b), h3 = h * sqr(h);
      return {h, a / h, b / h, sqr(b) / h3, -(a * b) / h3, sqr(a) / h3};
    }
    default:
      return {entire_interval(), entire_interval(), entire_interval(),
              entire_interval(), entire_interval(), entire_interval()};
  }
}

/// min or max taking a (take_a), b (take_b) or either somewhere in the box.
IntervalJet2 select(const IntervalJet2& a, const IntervalJet2& b, bool take_a, bool take_b,
                    const Interval& v) {
  if (take_a && !take_b) return {v, a.g, a.h};
  if (take_b && !take_a) return {v, b.g, b.h};
  IntervalJet2 r{v, {}, {}};
  for (std::size_t k = 0; k < 3; ++k) r.g[k] = hull(a.g[k], b.g[k]);
  for (std::size_t k = 0; k < 6; ++k) r.h[k] = entire_interval();  // the gradient may jump
  return r;
}

bool is_zero(const Interval& v) {
  return v.lo == 0.0 && v.hi == 0.0;
}

/// a * b and a + b with an exact zero operand taken as such: the same result (interval_math.hpp's
/// product is 0 when a factor is [0, 0]), without the rounding work. Most entries of a jet are exact
/// zeros when f is a sum of terms in fewer variables (the Chmutov surface's T6(x) + T6(y) + T6(z)).
Interval times(const Interval& a, const Interval& b) {
  if ((is_zero(a) && !b.empty()) || (is_zero(b) && !a.empty())) return Interval{0.0, 0.0};
  return a * b;
}
Interval plus(const Interval& a, const Interval& b) {
  if (is_zero(a)) return b;
  if (is_zero(b)) return a;
  return a + b;
}

/// a.g_i a.g_j: sqr on the diagonal (tight, and never negative).
Interval gradient_product(const IntervalJet2& a, std::size_t i, std::size_t j) {
  return i == j ? sqr(a.g[i]) : times(a.g[i], a.g[j]);
}

IntervalJet2 step(const Instruction& in, const IntervalJet2& a, const IntervalJet2& b) {
  IntervalJet2 r;
  switch (in.op) {
    case Op::Add:
    case Op::Sub: {
      const bool add = in.op == Op::Add;
      r.v = add ? a.v + b.v : a.v - b.v;
      for (std::size_t k = 0; k < 3; ++k) r.g[k] = add ? plus(a.g[k], b.g[k]) : plus(a.g[k], -b.g[k]);
      for (std::size_t k = 0; k < 6; ++k) r.h[k] = add ? plus(a.h[k], b.h[k]) : plus(a.h[k], -b.h[k]);
      return r;
    }
    case Op::Min:
      return select(a, b, !(b.v.hi < a.v.lo), b.v.lo < a.v.hi, min(a.v, b.v));
    case Op::Max:
      return select(a, b, !(a.v.hi < b.v.lo), a.v.lo < b.v.hi, max(a.v, b.v));
    case Op::Mul: {  // the common case, without the zero second derivatives of (a, b) -> a b
      r.v = a.v * b.v;
      for (std::size_t k = 0; k < 3; ++k) r.g[k] = plus(times(b.v, a.g[k]), times(a.v, b.g[k]));
      for (std::size_t k = 0; k < 6; ++k) {
        const auto i = static_cast<std::size_t>(kHessianRow[k]),
                   j = static_cast<std::size_t>(kHessianColumn[k]);
        r.h[k] = plus(plus(times(b.v, a.h[k]), times(a.v, b.h[k])),
                      plus(times(a.g[i], b.g[j]), times(a.g[j], b.g[i])));
      }
      return r;
    }
    case Op::Div:
    case Op::Pow:
    case Op::Atan2:
    case Op::Hypot: {
      const BinaryEnclosure d = binary_enclosure(in.op, a.v, b.v);
      r.v = d.f;
      for (std::size_t k = 0; k < 3; ++k) r.g[k] = d.fa * a.g[k] + d.fb * b.g[k];
      for (std::size_t k = 0; k < 6; ++k) {
        const auto i = static_cast<std::size_t>(kHessianRow[k]),
                   j = static_cast<std::size_t>(kHessianColumn[k]);
        r.h[k] = d.fa * a.h[k] + d.fb * b.h[k] + d.faa * gradient_product(a, i, j) +
                 d.fab * (a.g[i] * b.g[j] + a.g[j] * b.g[i]) + d.fbb * gradient_product(b, i, j);
      }
      return r;
    }
    default: {
      const UnaryEnclosure d = unary_enclosure(in.op, a.v, in.imm);
      r.v = d.v;
      for (std::size_t k = 0; k < 3; ++k) r.g[k] = times(d.d1, a.g[k]);
      const bool linear = is_zero(d.d2);  // +c, *c, -, /c: no second-derivative term
      for (std::size_t k = 0; k < 6; ++k) {
        const auto i = static_cast<std::size_t>(kHessianRow[k]),
                   j = static_cast<std::size_t>(kHessianColumn[k]);
        r.h[k] =
            linear ? times(d.d1, a.h[k]) : plus(times(d.d1, a.h[k]), times(d.d2, gradient_product(a, i, j)));
      }
      return r;
    }
  }
}

}  // namespace

IntervalHessian evaluate_interval_hessian(const Tape& tape, const Box& box) {
  thread_local std::vector<IntervalJet2> storage;
  if (storage.size() < tape.registers) storage.resize(tape.registers);
  IntervalJet2* r = storage.data();
  const Interval zero = exact_interval(0.0);
  for (int k = 0; k < 3; ++k) {
    r[k].v = {box.lo[k], box.hi[k]};
    for (int j = 0; j < 3; ++j) r[k].g[static_cast<std::size_t>(j)] = exact_interval(j == k ? 1.0 : 0.0);
    r[k].h.fill(zero);
  }
  for (const ConstantRegister& c : tape.constants) {
    r[c.reg].v = exact_interval(c.value);
    r[c.reg].g.fill(zero);
    r[c.reg].h.fill(zero);
  }
  for (const Instruction& in : tape.code) r[in.out] = step(in, r[in.a], r[in.b]);
  const IntervalJet2& f = r[tape.result];
  return {f.v, f.g, f.h};
}

}  // namespace isopatch::expr
