#pragma once
/// \file autodiff.hpp
/// Forward-mode automatic differentiation in three variables: the one jet type of the library. A
/// BasicJet<1> carries the value and the gradient of a function of (x, y, z); a BasicJet<2> (`Jet`) also
/// the symmetric Hessian. Arithmetic and the usual elementary functions propagate them exactly by the
/// chain rule (no finite differences). The formula evaluator (src/expr) keeps its registers in these
/// jets, the I-patch functions (src/composite_model) evaluate with them, and callable surfaces
/// (callable_surface.hpp) differentiate the caller's function with `Jet`.
///
/// Call math functions unqualified (`sin(x)`, not `std::sin(x)`) in code that must accept Jets;
/// argument-dependent lookup then finds the overloads below, and `<cmath>` serves plain doubles.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>

namespace isopatch {

// Inside namespace isopatch the Jet overloads below would hide the <cmath> ones for plain doubles;
// bring those in so generic code written in this namespace resolves for both types.
using std::abs, std::acos, std::asin, std::atan, std::atan2, std::cos, std::cosh, std::exp, std::hypot,
    std::log, std::max, std::min, std::pow, std::sin, std::sinh, std::sqrt, std::tan, std::tanh;

/// What a first-order jet holds in place of a Hessian: nothing.
struct NoHessian {};

/// The value of a function of (x, y, z) with its derivatives up to `Order` (1 or 2).
template <int Order>
struct BasicJet {
  static_assert(Order == 1 || Order == 2, "first or second order");

  double v = 0.0;             ///< value
  std::array<double, 3> g{};  ///< gradient
  /// Hessian, upper triangle: xx, xy, xz, yy, yz, zz (Order 2; takes no space in a BasicJet<1>).
  [[no_unique_address]] std::conditional_t<Order == 2, std::array<double, 6>, NoHessian> h{};

  BasicJet() = default;
  BasicJet(double value) : v(value) {}  // NOLINT: implicit on purpose, constants mix with Jets

  /// The independent variable number `axis` (0 = x, 1 = y, 2 = z) at `value`.
  static BasicJet variable(int axis, double value) {
    BasicJet j(value);
    j.g[static_cast<std::size_t>(axis)] = 1.0;
    return j;
  }

  /// Whether the value and every derivative are finite.
  bool finite() const {
    const auto is_finite = [](double x) { return std::isfinite(x); };
    bool all = std::isfinite(v) && std::all_of(g.begin(), g.end(), is_finite);
    if constexpr (Order == 2) all = all && std::all_of(h.begin(), h.end(), is_finite);
    return all;
  }

  // Operators taking two jets are hidden friends, so that a double on either side converts.
  friend BasicJet operator+(const BasicJet& a, const BasicJet& b) {
    BasicJet r(a.v + b.v);
    for (int i = 0; i < 3; ++i) r.g[i] = a.g[i] + b.g[i];
    if constexpr (Order == 2)
      for (std::size_t k = 0; k < 6; ++k) r.h[k] = a.h[k] + b.h[k];
    return r;
  }
  friend BasicJet operator-(const BasicJet& a, const BasicJet& b) { return a + (-b); }
  friend BasicJet operator*(const BasicJet& a, const BasicJet& b) {
    BasicJet r(a.v * b.v);
    for (int i = 0; i < 3; ++i) r.g[i] = a.v * b.g[i] + b.v * a.g[i];
    if constexpr (Order == 2) {
      int k = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j, ++k)
          r.h[k] = a.v * b.h[k] + b.v * a.h[k] + a.g[i] * b.g[j] + a.g[j] * b.g[i];
    }
    return r;
  }
  /// A constant times a jet: each part scaled (no products with the constant's zero derivatives).
  friend BasicJet operator*(double s, const BasicJet& a) {
    BasicJet r(s * a.v);
    for (int i = 0; i < 3; ++i) r.g[i] = s * a.g[i];
    if constexpr (Order == 2)
      for (std::size_t k = 0; k < 6; ++k) r.h[k] = s * a.h[k];
    return r;
  }
  friend BasicJet operator*(const BasicJet& a, double s) { return s * a; }
  /// The quotient rule: q = a / b, grad q = (grad a - q grad b) / b, and
  /// H q = (H a - q H b - grad q grad b^T - grad b grad q^T) / b.
  friend BasicJet operator/(const BasicJet& a, const BasicJet& b) {
    BasicJet r(a.v / b.v);
    for (int i = 0; i < 3; ++i) r.g[i] = (a.g[i] - r.v * b.g[i]) / b.v;
    if constexpr (Order == 2) {
      int k = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j, ++k)
          r.h[k] = (a.h[k] - r.v * b.h[k] - r.g[i] * b.g[j] - r.g[j] * b.g[i]) / b.v;
    }
    return r;
  }
  friend BasicJet& operator+=(BasicJet& a, const BasicJet& b) { return a = a + b; }
  friend BasicJet& operator-=(BasicJet& a, const BasicJet& b) { return a = a - b; }
  friend BasicJet& operator*=(BasicJet& a, const BasicJet& b) { return a = a * b; }
  friend BasicJet& operator/=(BasicJet& a, const BasicJet& b) { return a = a / b; }

  friend bool operator<(const BasicJet& a, const BasicJet& b) { return a.v < b.v; }
  friend bool operator>(const BasicJet& a, const BasicJet& b) { return a.v > b.v; }
  friend bool operator<=(const BasicJet& a, const BasicJet& b) { return a.v <= b.v; }
  friend bool operator>=(const BasicJet& a, const BasicJet& b) { return a.v >= b.v; }

  /// a^b with both varying: exp(b log a), defined for a > 0.
  friend BasicJet pow(const BasicJet& a, const BasicJet& b) { return exp(b * log(a)); }
  friend BasicJet hypot(const BasicJet& a, const BasicJet& b) { return sqrt(a * a + b * b); }
  friend BasicJet atan2(const BasicJet& y, const BasicJet& x) {
    // d atan2 = (x dy - y dx) / (x^2 + y^2); built from differentiable pieces.
    const double angle = std::atan2(y.v, x.v);
    BasicJet r = std::abs(x.v) >= std::abs(y.v) ? atan(y / x) : -atan(x / y);
    r.v = angle;
    return r;
  }
  friend BasicJet min(const BasicJet& a, const BasicJet& b) { return b.v < a.v ? b : a; }
  friend BasicJet max(const BasicJet& a, const BasicJet& b) { return a.v < b.v ? b : a; }
};

/// Value, gradient and Hessian.
using Jet = BasicJet<2>;
/// Value and gradient.
using GradientJet = BasicJet<1>;
static_assert(sizeof(GradientJet) == 4 * sizeof(double) && sizeof(Jet) == 10 * sizeof(double));

namespace detail {
/// Applies a scalar function with derivatives d1 = phi'(a.v), d2 = phi''(a.v) to a jet.
template <int N>
BasicJet<N> chain(const BasicJet<N>& a, double value, double d1, double d2) {
  BasicJet<N> r(value);
  for (int i = 0; i < 3; ++i) r.g[i] = d1 * a.g[i];
  if constexpr (N == 2) {
    int k = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j, ++k) r.h[k] = d1 * a.h[k] + d2 * a.g[i] * a.g[j];
  }
  return r;
}
}  // namespace detail

template <int N>
BasicJet<N> operator+(const BasicJet<N>& a) {
  return a;
}
template <int N>
BasicJet<N> operator-(const BasicJet<N>& a) {
  BasicJet<N> r(-a.v);
  for (int i = 0; i < 3; ++i) r.g[i] = -a.g[i];
  if constexpr (N == 2)
    for (std::size_t k = 0; k < 6; ++k) r.h[k] = -a.h[k];
  return r;
}
template <int N>
BasicJet<N> reciprocal(const BasicJet<N>& a) {
  const double inv = 1.0 / a.v;
  return detail::chain(a, inv, -inv * inv, 2.0 * inv * inv * inv);
}

template <int N>
BasicJet<N> sqrt(const BasicJet<N>& a) {
  const double s = std::sqrt(a.v);
  return detail::chain(a, s, 0.5 / s, -0.25 / (s * a.v));
}
template <int N>
BasicJet<N> exp(const BasicJet<N>& a) {
  const double e = std::exp(a.v);
  return detail::chain(a, e, e, e);
}
template <int N>
BasicJet<N> log(const BasicJet<N>& a) {
  return detail::chain(a, std::log(a.v), 1.0 / a.v, -1.0 / (a.v * a.v));
}
template <int N>
BasicJet<N> sin(const BasicJet<N>& a) {
  const double s = std::sin(a.v);
  return detail::chain(a, s, std::cos(a.v), -s);
}
template <int N>
BasicJet<N> cos(const BasicJet<N>& a) {
  const double c = std::cos(a.v);
  return detail::chain(a, c, -std::sin(a.v), -c);
}
template <int N>
BasicJet<N> tan(const BasicJet<N>& a) {
  const double t = std::tan(a.v);
  const double d1 = 1.0 + t * t;
  return detail::chain(a, t, d1, 2.0 * t * d1);
}
template <int N>
BasicJet<N> asin(const BasicJet<N>& a) {
  const double q = 1.0 - a.v * a.v;
  return detail::chain(a, std::asin(a.v), 1.0 / std::sqrt(q), a.v / (q * std::sqrt(q)));
}
template <int N>
BasicJet<N> acos(const BasicJet<N>& a) {
  const double q = 1.0 - a.v * a.v;
  return detail::chain(a, std::acos(a.v), -1.0 / std::sqrt(q), -a.v / (q * std::sqrt(q)));
}
template <int N>
BasicJet<N> atan(const BasicJet<N>& a) {
  const double q = 1.0 + a.v * a.v;
  return detail::chain(a, std::atan(a.v), 1.0 / q, -2.0 * a.v / (q * q));
}
template <int N>
BasicJet<N> sinh(const BasicJet<N>& a) {
  const double s = std::sinh(a.v);
  return detail::chain(a, s, std::cosh(a.v), s);
}
template <int N>
BasicJet<N> cosh(const BasicJet<N>& a) {
  const double c = std::cosh(a.v);
  return detail::chain(a, c, std::sinh(a.v), c);
}
template <int N>
BasicJet<N> tanh(const BasicJet<N>& a) {
  const double t = std::tanh(a.v);
  const double d1 = 1.0 - t * t;
  return detail::chain(a, t, d1, -2.0 * t * d1);
}
template <int N>
BasicJet<N> abs(const BasicJet<N>& a) {
  return a.v < 0.0 ? -a : a;
}
/// a^p for a constant exponent p (any real p; for a < 0 only integer p give finite results).
template <int N>
BasicJet<N> pow(const BasicJet<N>& a, double p) {
  if (p == 0.0) return BasicJet<N>(1.0);
  if (p == 1.0) return a;
  if (p == 2.0) return a * a;
  const double v = std::pow(a.v, p);
  const double d1 = p * std::pow(a.v, p - 1.0);
  const double d2 = p * (p - 1.0) * std::pow(a.v, p - 2.0);
  return detail::chain(a, v, d1, d2);
}
template <int N>
BasicJet<N> pow(const BasicJet<N>& a, int p) {
  return pow(a, static_cast<double>(p));
}
template <int N>
BasicJet<N> pow(double a, const BasicJet<N>& b) {
  return exp(b * std::log(a));
}

}  // namespace isopatch
