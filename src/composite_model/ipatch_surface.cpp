/// \file ipatch_surface.cpp
/// The I-patch function, its weights and its exact derivatives (ipatch_surface.hpp).
#include "composite_model/ipatch_surface.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace isopatch {

namespace {

/// A value with its gradient; the arithmetic is the chain rule, written out.
struct Jet1 {
  double v = 0.0;
  Vec3 g = Vec3::Zero();
};

/// A value with its gradient and Hessian.
struct Jet2 {
  double v = 0.0;
  Vec3 g = Vec3::Zero();
  Mat3 h = Mat3::Zero();
};

Jet1 operator+(const Jet1& a, const Jet1& b) {
  return {a.v + b.v, a.g + b.g};
}
Jet1 operator*(double s, const Jet1& a) {
  return {s * a.v, s * a.g};
}
Jet1 operator*(const Jet1& a, const Jet1& b) {
  return {a.v * b.v, a.v * b.g + b.v * a.g};
}
Jet1 operator/(const Jet1& n, const Jet1& d) {
  const double q = n.v / d.v;
  return {q, (n.g - q * d.g) / d.v};
}

Jet2 operator+(const Jet2& a, const Jet2& b) {
  return {a.v + b.v, a.g + b.g, a.h + b.h};
}
Jet2 operator*(double s, const Jet2& a) {
  return {s * a.v, s * a.g, s * a.h};
}
Jet2 operator*(const Jet2& a, const Jet2& b) {
  const Mat3 cross = a.g * b.g.transpose();
  return {a.v * b.v, a.v * b.g + b.v * a.g, a.v * b.h + b.v * a.h + cross + cross.transpose()};
}
Jet2 operator/(const Jet2& n, const Jet2& d) {
  const double q = n.v / d.v;
  const Vec3 gq = (n.g - q * d.g) / d.v;
  const Mat3 cross = gq * d.g.transpose();
  return {q, gq, (n.h - q * d.h - cross - cross.transpose()) / d.v};
}

template <typename T>
T load(const Surface& s, const Vec3& p) {
  if constexpr (std::is_same_v<T, double>) {
    return s.value(p);
  } else if constexpr (std::is_same_v<T, Jet1>) {
    const ValueGradient o = s.value_gradient(p);
    return {o.value, o.gradient};
  } else {
    const SecondOrder o = s.second_order(p);
    return {o.value, o.gradient, o.hessian};
  }
}

template <typename T>
T constant(double v) {
  if constexpr (std::is_same_v<T, double>) {
    return v;
  } else {
    T t;
    t.v = v;
    return t;
  }
}

template <typename T>
double val(const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    return x;
  } else {
    return x.v;
  }
}

template <typename T>
bool finite(const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    return std::isfinite(x);
  } else if constexpr (std::is_same_v<T, Jet1>) {
    return std::isfinite(x.v) && x.g.allFinite();
  } else {
    return std::isfinite(x.v) && x.g.allFinite() && x.h.allFinite();
  }
}

}  // namespace

IPatchWeights rule_a_weights(const std::vector<SurfacePtr>& ribbons, const std::vector<SurfacePtr>& bounds,
                             const Vec3& centre, const std::vector<double>& d, const std::string& patch) {
  const std::size_t n = ribbons.size();
  if (bounds.size() != n) throw InputError(patch + ": as many bounding functions as ribbons are needed");
  if (!d.empty() && d.size() != n) {
    throw InputError(patch + ": " + std::to_string(d.size()) + " weight factors given for " +
                     std::to_string(n) + " sides");
  }
  IPatchWeights out;
  int sign = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double di = d.empty() ? 1.0 : d[i];
    if (!(di > 0.0) || !std::isfinite(di)) throw InputError(patch + ": weight factors must be positive");
    const double r = ribbons[i]->value(centre);
    const double b = bounds[i]->value(centre);
    if (!(b > 0.0)) {
      throw InputError(patch + ": the reference point lies outside the patch's region (side " +
                       std::to_string(i + 1) + ")");
    }
    if (!(r != 0.0) || !std::isfinite(r)) {
      throw InputError(patch + ": the reference point lies on ribbon " + std::to_string(i + 1));
    }
    const int s = r > 0.0 ? 1 : -1;
    if (sign != 0 && s != sign) {
      throw InputError(patch +
                       ": the ribbons differ in sign at the reference point (it is inside some "
                       "and outside others); choose another centre");
    }
    sign = s;
    out.w.push_back(di * b * b / std::abs(r));
    out.w0 -= di * s;
  }
  return out;
}

IPatchSurface::IPatchSurface(std::string name, Box box, std::vector<SurfacePtr> ribbons,
                             std::vector<SurfacePtr> bounds, IPatchWeights weights)
    : Surface(std::move(name), box),
      ribbons_(std::move(ribbons)),
      bounds_(std::move(bounds)),
      weights_(std::move(weights)) {
  const std::size_t n = ribbons_.size();
  if (n < 2 || bounds_.size() != n || weights_.w.size() != n) {
    throw InputError(this->name() + ": an I-patch needs n >= 2 ribbons, bounds and weights");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!ribbons_[i] || !bounds_[i]) throw InputError(this->name() + ": missing ribbon or bounding function");
    if (!(weights_.w[i] > 0.0) || !std::isfinite(weights_.w[i])) {
      throw InputError(this->name() + ": I-patch weights must be positive and finite");
    }
  }
  if (!std::isfinite(weights_.w0)) throw InputError(this->name() + ": the weight w0 is not finite");
}

template <typename T>
T IPatchSurface::evaluate(const Vec3& p) const {
  // One pass, no storage: with P = prod_{k<j} B_k^2, A = sum_{i<j} w_i R_i prod_{k<j, k!=i} B_k^2 and D
  // likewise without R_i, adding side j multiplies A and D by B_j^2 and adds w_j R_j P and w_j P.
  const std::size_t n = ribbons_.size();
  T product = constant<T>(1.0), numerator = constant<T>(0.0), denominator = constant<T>(0.0);
  for (std::size_t j = 0; j < n; ++j) {
    const T r = load<T>(*ribbons_[j], p);
    const T b = load<T>(*bounds_[j], p);
    const T square = b * b;
    numerator = numerator * square + weights_.w[j] * (r * product);
    denominator = denominator * square + weights_.w[j] * product;
    product = product * square;
  }
  numerator = numerator + weights_.w0 * product;
  if (val(denominator) > 0.0) {
    const T q = numerator / denominator;
    if (finite(q)) return q;
  }
  // 0/0: two or more bounding functions vanish (or the products underflow). The mean of the ribbons of
  // the vanishing sides (of the two nearest ones when fewer are exactly zero) is finite and lies between
  // the one-sided limits.
  const auto size_of = [&](std::size_t j) { return std::abs(bounds_[j]->value(p)); };
  std::size_t first = 0;  // the two smallest |B_j|
  for (std::size_t j = 1; j < n; ++j) {
    if (size_of(j) < size_of(first)) first = j;
  }
  std::size_t second = first == 0 ? 1 : 0;
  for (std::size_t j = 0; j < n; ++j) {
    if (j != first && size_of(j) < size_of(second)) second = j;
  }
  T mean = load<T>(*ribbons_[first], p) + load<T>(*ribbons_[second], p);
  std::size_t count = 2;
  for (std::size_t j = 0; j < n; ++j) {
    if (j != first && j != second && size_of(j) == 0.0) {
      mean = mean + load<T>(*ribbons_[j], p);
      ++count;
    }
  }
  return (1.0 / static_cast<double>(count)) * mean;
}

double IPatchSurface::value(const Vec3& p) const {
  return evaluate<double>(p);
}

ValueGradient IPatchSurface::value_gradient(const Vec3& p) const {
  const Jet1 j = evaluate<Jet1>(p);
  return {j.v, j.g};
}

SecondOrder IPatchSurface::second_order(const Vec3& p) const {
  const Jet2 j = evaluate<Jet2>(p);
  return {j.v, j.g, j.h};
}

double IPatchSurface::plain_value(const Vec3& p) const {
  const std::size_t n = ribbons_.size();
  std::vector<double> r(n), s(n);
  for (std::size_t i = 0; i < n; ++i) {
    r[i] = ribbons_[i]->value(p);
    const double b = bounds_[i]->value(p);
    s[i] = b * b;
  }
  double all = weights_.w0;
  for (double x : s) all *= x;
  double sum = all;
  for (std::size_t i = 0; i < n; ++i) {
    double term = weights_.w[i] * r[i];
    for (std::size_t j = 0; j < n; ++j) {
      if (j != i) term *= s[j];
    }
    sum += term;
  }
  return sum;
}

double IPatchSurface::region_margin(const Vec3& p) const {
  double m = std::numeric_limits<double>::infinity();
  for (const auto& b : bounds_) m = std::min(m, b->value(p));
  return m;
}

}  // namespace isopatch
