// Interval arithmetic (interval_math.hpp). Each endpoint is an operation evaluated at an endpoint of
// the operands, so by monotonicity of round-to-nearest it bounds the value computed at any inner
// point; moving it outward (by one ulp for correctly rounded operations, kLibmUlps for libm, whose
// glibc error is below one ulp) makes it bound the exact value as well.
#include <isopatch/interval_math.hpp>

#include "expr/scalar.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace isopatch {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;
constexpr int kLibmUlps = 4;

double next_down(double x) {
  if (!(x > -kInf)) return x;  // -inf and NaN stay
  if (x == 0.0) return -std::numeric_limits<double>::denorm_min();
  auto bits = std::bit_cast<std::uint64_t>(x);
  bits = x > 0.0 ? bits - 1 : bits + 1;
  return std::bit_cast<double>(bits);
}
double next_up(double x) {
  return -next_down(-x);
}

double down(double x, int ulps) {
  for (int i = 0; i < ulps; ++i) x = next_down(x);
  return x;
}
double up(double x, int ulps) {
  for (int i = 0; i < ulps; ++i) x = next_up(x);
  return x;
}

/// [lo, hi] moved outward; a NaN endpoint (inf - inf, 0 * inf in a limit) becomes unbounded.
Interval outward(double lo, double hi, int ulps = 1) {
  lo = std::isnan(lo) ? -kInf : down(lo, ulps);
  hi = std::isnan(hi) ? kInf : up(hi, ulps);
  return {lo, hi};
}

Interval clamp(Interval r, double lo, double hi) {
  return {std::max(r.lo, lo), std::min(r.hi, hi)};
}

/// Product with 0 * inf = 0: a zero operand at a point gives 0 whatever the other finite value.
double mul0(double a, double b) {
  return (a == 0.0 || b == 0.0) ? 0.0 : a * b;
}

double mig(const Interval& a) {
  return a.contains_zero() ? 0.0 : std::min(std::fabs(a.lo), std::fabs(a.hi));
}
double mag(const Interval& a) {
  return std::max(std::fabs(a.lo), std::fabs(a.hi));
}

/// True when [lo, hi] may contain offset + k * period for some integer k (errs towards true).
bool may_contain_periodic(double lo, double hi, double offset, double period) {
  const double a = (lo - offset) / period;
  const double b = (hi - offset) / period;
  const double slack = 1e-9 + 1e-12 * std::max(std::fabs(a), std::fabs(b));
  return std::floor(b + slack) >= std::ceil(a - slack);
}

bool huge(const Interval& a) {
  return !(std::fabs(a.lo) < 1e12 && std::fabs(a.hi) < 1e12);
}

/// The image of a non-decreasing function: [f(lo), f(hi)] widened.
template <class F>
Interval increasing(const Interval& a, F f, int ulps = kLibmUlps) {
  return outward(f(a.lo), f(a.hi), ulps);
}

/// pow on a non-negative base: monotone in each argument, so the extremes are at the corners.
Interval pow_nonnegative_base(const Interval& a, const Interval& b) {
  // A zero end may be -0 (from negating [-x, 0]); pow(-0, -3) is -inf, not +inf as for the real base 0.
  const double lo = a.lo <= 0.0 ? 0.0 : a.lo;
  const double hi = a.hi <= 0.0 ? 0.0 : a.hi;
  const double c[4] = {std::pow(lo, b.lo), std::pow(lo, b.hi), std::pow(hi, b.lo), std::pow(hi, b.hi)};
  return clamp(outward(*std::min_element(c, c + 4), *std::max_element(c, c + 4), kLibmUlps), 0.0, kInf);
}

}  // namespace

Interval entire_interval() {
  return {-kInf, kInf};
}
Interval empty_interval() {
  return {kInf, -kInf};
}

Interval hull(const Interval& a, const Interval& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

Interval intersect(const Interval& a, const Interval& b) {
  const Interval r{std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
  return r.empty() ? empty_interval() : r;
}

Interval operator-(const Interval& a) {
  return a.empty() ? a : Interval{-a.hi, -a.lo};
}

Interval operator+(const Interval& a, const Interval& b) {
  if (a.empty() || b.empty()) return empty_interval();
  return outward(a.lo + b.lo, a.hi + b.hi);
}

Interval operator-(const Interval& a, const Interval& b) {
  if (a.empty() || b.empty()) return empty_interval();
  return outward(a.lo - b.hi, a.hi - b.lo);
}

Interval operator*(const Interval& a, const Interval& b) {
  if (a.empty() || b.empty()) return empty_interval();
  const double p[4] = {mul0(a.lo, b.lo), mul0(a.lo, b.hi), mul0(a.hi, b.lo), mul0(a.hi, b.hi)};
  return outward(*std::min_element(p, p + 4), *std::max_element(p, p + 4));
}

Interval operator/(const Interval& a, const Interval& b) {
  if (a.empty() || b.empty()) return empty_interval();
  if (b.lo > 0.0 || b.hi < 0.0) {
    const double q[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
    if (std::any_of(q, q + 4, [](double v) { return std::isnan(v); })) return entire_interval();
    return outward(*std::min_element(q, q + 4), *std::max_element(q, q + 4));
  }
  if (b.lo == 0.0 && b.hi == 0.0) return entire_interval();
  if (a.lo == 0.0 && a.hi == 0.0) return {0.0, 0.0};
  if (b.lo == 0.0) {  // (0, b.hi]
    if (a.lo >= 0.0) return outward(a.lo / b.hi, kInf);
    if (a.hi <= 0.0) return outward(-kInf, a.hi / b.hi);
  } else if (b.hi == 0.0) {  // [b.lo, 0)
    if (a.lo >= 0.0) return outward(-kInf, a.lo / b.lo);
    if (a.hi <= 0.0) return outward(a.hi / b.lo, kInf);
  }
  return entire_interval();
}

Interval sqr(const Interval& a) {
  if (a.empty()) return a;
  const double l = mig(a), h = mag(a);
  return clamp(outward(l * l, h * h), 0.0, kInf);
}

Interval powi(const Interval& a, int n) {
  if (a.empty()) return a;
  if (n < 0) return Interval{1.0, 1.0} / powi(a, -n);
  if (n == 0) return {1.0, 1.0};
  const auto un = static_cast<unsigned>(n);
  const int ulps = 2 * std::bit_width(un);
  if (n % 2 == 0) return clamp(outward(expr::ipow(mig(a), un), expr::ipow(mag(a), un), ulps), 0.0, kInf);
  return outward(expr::ipow(a.lo, un), expr::ipow(a.hi, un), ulps);
}

Interval pow(const Interval& a, double p) {
  if (a.empty() || std::isnan(p)) return empty_interval();
  if (p == 0.0) return {1.0, 1.0};
  const auto f = [p](double v) { return std::pow(v, p); };
  if (p == std::trunc(p) && std::isfinite(p)) {  // every base is in the domain
    const bool even = std::fmod(p, 2.0) == 0.0;
    if (p > 0.0) {
      if (even) return clamp(outward(f(mig(a)), f(mag(a)), kLibmUlps), 0.0, kInf);
      return increasing(a, f);
    }
    // Negative integer: 1 / |x|^-p, with the sign of x for odd p.
    if (a.contains_zero()) {
      if (even) return outward(f(mag(a)), kInf, kLibmUlps);
      if (a.lo == 0.0) return outward(f(a.hi), kInf, kLibmUlps);
      if (a.hi == 0.0) return outward(-kInf, f(a.lo), kLibmUlps);
      return entire_interval();
    }
    if (even) return outward(f(mag(a)), f(mig(a)), kLibmUlps);
    return outward(f(a.hi), f(a.lo), kLibmUlps);  // decreasing on each side of 0
  }
  const Interval d = intersect(a, {0.0, kInf});
  if (d.empty()) return d;
  if (p > 0.0) return clamp(increasing(d, f), 0.0, kInf);
  return clamp(outward(f(d.hi), f(d.lo), kLibmUlps), 0.0, kInf);
}

Interval pow(const Interval& a, const Interval& b) {
  if (a.empty() || b.empty()) return empty_interval();
  if (b.lo == b.hi) return pow(a, b.lo);
  Interval r = empty_interval();
  const Interval positive = intersect(a, {0.0, kInf});
  if (!positive.empty()) r = pow_nonnegative_base(positive, b);
  // A negative base has real powers only at integer exponents: |x|^k with either sign.
  const Interval negative = intersect(a, {-kInf, 0.0});
  if (!negative.empty() && std::floor(b.hi) >= std::ceil(b.lo)) {
    const double m = pow_nonnegative_base(-negative, b).hi;
    r = hull(r, {-m, m});
  }
  return r;
}

Interval sqrt(const Interval& a) {
  const Interval d = intersect(a, {0.0, kInf});
  if (d.empty()) return d;
  return clamp(outward(std::sqrt(d.lo), std::sqrt(d.hi)), 0.0, kInf);
}

Interval exp(const Interval& a) {
  if (a.empty()) return a;
  return clamp(increasing(a, [](double v) { return std::exp(v); }), 0.0, kInf);
}

Interval log(const Interval& a) {
  const Interval d = intersect(a, {0.0, kInf});
  if (d.empty()) return d;
  return increasing(d, [](double v) { return std::log(v); });
}

Interval sin(const Interval& a) {
  if (a.empty()) return a;
  if (huge(a) || !(a.width() < 2.0 * kPi)) return {-1.0, 1.0};
  const double s0 = std::sin(a.lo), s1 = std::sin(a.hi);
  Interval r = outward(std::min(s0, s1), std::max(s0, s1), kLibmUlps);
  if (may_contain_periodic(a.lo, a.hi, 0.5 * kPi, 2.0 * kPi)) r.hi = 1.0;
  if (may_contain_periodic(a.lo, a.hi, -0.5 * kPi, 2.0 * kPi)) r.lo = -1.0;
  return clamp(r, -1.0, 1.0);
}

Interval cos(const Interval& a) {
  if (a.empty()) return a;
  if (huge(a) || !(a.width() < 2.0 * kPi)) return {-1.0, 1.0};
  const double c0 = std::cos(a.lo), c1 = std::cos(a.hi);
  Interval r = outward(std::min(c0, c1), std::max(c0, c1), kLibmUlps);
  if (may_contain_periodic(a.lo, a.hi, 0.0, 2.0 * kPi)) r.hi = 1.0;
  if (may_contain_periodic(a.lo, a.hi, kPi, 2.0 * kPi)) r.lo = -1.0;
  return clamp(r, -1.0, 1.0);
}

Interval tan(const Interval& a) {
  if (a.empty()) return a;
  if (huge(a) || !(a.width() < kPi) || may_contain_periodic(a.lo, a.hi, 0.5 * kPi, kPi))
    return entire_interval();
  return increasing(a, [](double v) { return std::tan(v); });
}

Interval asin(const Interval& a) {
  const Interval d = intersect(a, {-1.0, 1.0});
  if (d.empty()) return d;
  return increasing(d, [](double v) { return std::asin(v); });
}

Interval acos(const Interval& a) {
  const Interval d = intersect(a, {-1.0, 1.0});
  if (d.empty()) return d;
  return clamp(outward(std::acos(d.hi), std::acos(d.lo), kLibmUlps), 0.0, kInf);
}

Interval atan(const Interval& a) {
  if (a.empty()) return a;
  return increasing(a, [](double v) { return std::atan(v); });
}

Interval sinh(const Interval& a) {
  if (a.empty()) return a;
  return increasing(a, [](double v) { return std::sinh(v); });
}

Interval cosh(const Interval& a) {
  if (a.empty()) return a;
  return clamp(outward(std::cosh(mig(a)), std::cosh(mag(a)), kLibmUlps), 1.0, kInf);
}

Interval tanh(const Interval& a) {
  if (a.empty()) return a;
  return clamp(increasing(a, [](double v) { return std::tanh(v); }), -1.0, 1.0);
}

Interval abs(const Interval& a) {
  if (a.empty()) return a;
  return {mig(a), mag(a)};
}

// std::min(a, b) returns a when b is NaN and NaN when a is: an empty b leaves a, an empty a stays.
Interval min(const Interval& a, const Interval& b) {
  if (a.empty() || b.empty()) return a;
  return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
}

Interval max(const Interval& a, const Interval& b) {
  if (a.empty() || b.empty()) return a;
  return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
}

Interval hypot(const Interval& a, const Interval& b) {
  if (a.empty() || b.empty()) return empty_interval();
  return clamp(outward(std::hypot(mig(a), mig(b)), std::hypot(mag(a), mag(b)), kLibmUlps), 0.0, kInf);
}

Interval atan2(const Interval& y, const Interval& x) {
  if (y.empty() || x.empty()) return empty_interval();
  const Interval all = outward(-kPi, kPi, kLibmUlps);
  // Across the branch cut (the negative x axis, where the angle jumps from pi to -pi) or around the
  // origin every angle occurs; elsewhere the angle is monotone along the box edges, so the extremes
  // are at the corners.
  // x.lo = 0 counts too: the point evaluators may see x = -0 there, and atan2(0, -0) = pi.
  if (x.lo <= 0.0 && y.contains_zero()) return all;
  const double c[4] = {std::atan2(y.lo, x.lo), std::atan2(y.lo, x.hi), std::atan2(y.hi, x.lo),
                       std::atan2(y.hi, x.hi)};
  if (std::any_of(c, c + 4, [](double v) { return std::isnan(v); })) return all;
  return clamp(outward(*std::min_element(c, c + 4), *std::max_element(c, c + 4), kLibmUlps), all.lo, all.hi);
}

}  // namespace isopatch
