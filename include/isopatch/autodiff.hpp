#pragma once
/// \file autodiff.hpp
/// Second-order forward-mode automatic differentiation in three variables. A Jet carries the value,
/// the gradient and the symmetric Hessian of a function of (x, y, z); arithmetic and the usual
/// elementary functions propagate them exactly by the chain rule (no finite differences).
///
/// Call math functions unqualified (`sin(x)`, not `std::sin(x)`) in code that must accept Jets;
/// argument-dependent lookup then finds the overloads below, and `<cmath>` serves plain doubles.

#include <algorithm>
#include <array>
#include <cmath>

namespace isopatch {

// Inside namespace isopatch the Jet overloads below would hide the <cmath> ones for plain doubles;
// bring those in so generic code written in this namespace resolves for both types.
using std::abs, std::acos, std::asin, std::atan, std::atan2, std::cos, std::cosh, std::exp, std::hypot,
    std::log, std::max, std::min, std::pow, std::sin, std::sinh, std::sqrt, std::tan, std::tanh;

struct Jet {
  double v = 0.0;             ///< value
  std::array<double, 3> g{};  ///< gradient
  std::array<double, 6> h{};  ///< Hessian, upper triangle: xx, xy, xz, yy, yz, zz

  Jet() = default;
  Jet(double value) : v(value) {}  // NOLINT: implicit on purpose, constants mix with Jets

  /// The independent variable number `axis` (0 = x, 1 = y, 2 = z) at `value`.
  static Jet variable(int axis, double value) {
    Jet j(value);
    j.g[static_cast<std::size_t>(axis)] = 1.0;
    return j;
  }
};

namespace detail {
/// Applies a scalar function with derivatives d1 = phi'(a.v), d2 = phi''(a.v) to a Jet.
inline Jet chain(const Jet& a, double value, double d1, double d2) {
  Jet r(value);
  for (int i = 0; i < 3; ++i) r.g[i] = d1 * a.g[i];
  int k = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j, ++k) r.h[k] = d1 * a.h[k] + d2 * a.g[i] * a.g[j];
  return r;
}
}  // namespace detail

inline Jet operator+(const Jet& a) {
  return a;
}
inline Jet operator-(const Jet& a) {
  Jet r(-a.v);
  for (int i = 0; i < 3; ++i) r.g[i] = -a.g[i];
  for (int k = 0; k < 6; ++k) r.h[k] = -a.h[k];
  return r;
}
inline Jet operator+(const Jet& a, const Jet& b) {
  Jet r(a.v + b.v);
  for (int i = 0; i < 3; ++i) r.g[i] = a.g[i] + b.g[i];
  for (int k = 0; k < 6; ++k) r.h[k] = a.h[k] + b.h[k];
  return r;
}
inline Jet operator-(const Jet& a, const Jet& b) {
  return a + (-b);
}
inline Jet operator*(const Jet& a, const Jet& b) {
  Jet r(a.v * b.v);
  for (int i = 0; i < 3; ++i) r.g[i] = a.v * b.g[i] + b.v * a.g[i];
  int k = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j, ++k) r.h[k] = a.v * b.h[k] + b.v * a.h[k] + a.g[i] * b.g[j] + a.g[j] * b.g[i];
  return r;
}
inline Jet reciprocal(const Jet& a) {
  const double inv = 1.0 / a.v;
  return detail::chain(a, inv, -inv * inv, 2.0 * inv * inv * inv);
}
inline Jet operator/(const Jet& a, const Jet& b) {
  return a * reciprocal(b);
}
inline Jet& operator+=(Jet& a, const Jet& b) {
  return a = a + b;
}
inline Jet& operator-=(Jet& a, const Jet& b) {
  return a = a - b;
}
inline Jet& operator*=(Jet& a, const Jet& b) {
  return a = a * b;
}
inline Jet& operator/=(Jet& a, const Jet& b) {
  return a = a / b;
}

inline bool operator<(const Jet& a, const Jet& b) {
  return a.v < b.v;
}
inline bool operator>(const Jet& a, const Jet& b) {
  return a.v > b.v;
}
inline bool operator<=(const Jet& a, const Jet& b) {
  return a.v <= b.v;
}
inline bool operator>=(const Jet& a, const Jet& b) {
  return a.v >= b.v;
}

inline Jet sqrt(const Jet& a) {
  const double s = std::sqrt(a.v);
  return detail::chain(a, s, 0.5 / s, -0.25 / (s * a.v));
}
inline Jet exp(const Jet& a) {
  const double e = std::exp(a.v);
  return detail::chain(a, e, e, e);
}
inline Jet log(const Jet& a) {
  return detail::chain(a, std::log(a.v), 1.0 / a.v, -1.0 / (a.v * a.v));
}
inline Jet sin(const Jet& a) {
  const double s = std::sin(a.v);
  return detail::chain(a, s, std::cos(a.v), -s);
}
inline Jet cos(const Jet& a) {
  const double c = std::cos(a.v);
  return detail::chain(a, c, -std::sin(a.v), -c);
}
inline Jet tan(const Jet& a) {
  const double t = std::tan(a.v);
  const double d1 = 1.0 + t * t;
  return detail::chain(a, t, d1, 2.0 * t * d1);
}
inline Jet asin(const Jet& a) {
  const double q = 1.0 - a.v * a.v;
  return detail::chain(a, std::asin(a.v), 1.0 / std::sqrt(q), a.v / (q * std::sqrt(q)));
}
inline Jet acos(const Jet& a) {
  const double q = 1.0 - a.v * a.v;
  return detail::chain(a, std::acos(a.v), -1.0 / std::sqrt(q), -a.v / (q * std::sqrt(q)));
}
inline Jet atan(const Jet& a) {
  const double q = 1.0 + a.v * a.v;
  return detail::chain(a, std::atan(a.v), 1.0 / q, -2.0 * a.v / (q * q));
}
inline Jet sinh(const Jet& a) {
  const double s = std::sinh(a.v);
  return detail::chain(a, s, std::cosh(a.v), s);
}
inline Jet cosh(const Jet& a) {
  const double c = std::cosh(a.v);
  return detail::chain(a, c, std::sinh(a.v), c);
}
inline Jet tanh(const Jet& a) {
  const double t = std::tanh(a.v);
  const double d1 = 1.0 - t * t;
  return detail::chain(a, t, d1, -2.0 * t * d1);
}
inline Jet abs(const Jet& a) {
  return a.v < 0.0 ? -a : a;
}
/// a^p for a constant exponent p (any real p; for a < 0 only integer p give finite results).
inline Jet pow(const Jet& a, double p) {
  if (p == 0.0) return Jet(1.0);
  if (p == 1.0) return a;
  if (p == 2.0) return a * a;
  const double v = std::pow(a.v, p);
  const double d1 = p * std::pow(a.v, p - 1.0);
  const double d2 = p * (p - 1.0) * std::pow(a.v, p - 2.0);
  return detail::chain(a, v, d1, d2);
}
inline Jet pow(const Jet& a, int p) {
  return pow(a, static_cast<double>(p));
}
/// a^b with both varying: exp(b log a), defined for a > 0.
inline Jet pow(const Jet& a, const Jet& b) {
  return exp(b * log(a));
}
inline Jet pow(double a, const Jet& b) {
  return exp(b * std::log(a));
}
inline Jet hypot(const Jet& a, const Jet& b) {
  return sqrt(a * a + b * b);
}
inline Jet atan2(const Jet& y, const Jet& x) {
  // d atan2 = (x dy - y dx) / (x^2 + y^2); built from differentiable pieces.
  const double angle = std::atan2(y.v, x.v);
  if (std::abs(x.v) >= std::abs(y.v)) {
    Jet r = atan(y / x);
    r.v = angle;
    return r;
  }
  Jet r = -atan(x / y);
  r.v = angle;
  return r;
}
inline Jet min(const Jet& a, const Jet& b) {
  return b.v < a.v ? b : a;
}
inline Jet max(const Jet& a, const Jet& b) {
  return a.v < b.v ? b : a;
}

}  // namespace isopatch
