/// \file ipatch_surface.cpp
/// The I-patch function, its weights and its exact derivatives (ipatch_surface.hpp).
#include "ipatch/ipatch_surface.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace isopatch {

namespace {

/// A value with its gradient and Hessian; the arithmetic is the chain rule, written out.
struct Jet {
  double v = 0.0;
  Vec3 g = Vec3::Zero();
  Mat3 h = Mat3::Zero();
};

Jet constant(double v) {
  return {v, Vec3::Zero(), Mat3::Zero()};
}

Jet operator+(const Jet& a, const Jet& b) {
  return {a.v + b.v, a.g + b.g, a.h + b.h};
}

Jet operator*(double s, const Jet& a) {
  return {s * a.v, s * a.g, s * a.h};
}

Jet operator*(const Jet& a, const Jet& b) {
  const Mat3 cross = a.g * b.g.transpose();
  return {a.v * b.v, a.v * b.g + b.v * a.g, a.v * b.h + b.v * a.h + cross + cross.transpose()};
}

Jet operator/(const Jet& n, const Jet& d) {
  const double q = n.v / d.v;
  const Vec3 gq = (n.g - q * d.g) / d.v;
  const Mat3 cross = gq * d.g.transpose();
  return {q, gq, (n.h - q * d.h - cross - cross.transpose()) / d.v};
}

Jet load(const Surface& s, const Vec3& p) {
  const SecondOrder o = s.second_order(p);
  return {o.value, o.gradient, o.hessian};
}

double load_value(const Surface& s, const Vec3& p) {
  return s.value(p);
}

template <typename T>
bool finite(const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    return std::isfinite(x);
  } else {
    return std::isfinite(x.v) && x.g.allFinite() && x.h.allFinite();
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
  const std::size_t n = ribbons_.size();
  std::vector<T> r(n), b(n), squares(n);
  for (std::size_t i = 0; i < n; ++i) {
    if constexpr (std::is_same_v<T, double>) {
      r[i] = load_value(*ribbons_[i], p);
      b[i] = load_value(*bounds_[i], p);
    } else {
      r[i] = load(*ribbons_[i], p);
      b[i] = load(*bounds_[i], p);
    }
    squares[i] = b[i] * b[i];
  }
  // prefix[k] = prod_{j<k} B_j^2, suffix[k] = prod_{j>=k} B_j^2.
  std::vector<T> prefix(n + 1), suffix(n + 1);
  if constexpr (std::is_same_v<T, double>) {
    prefix[0] = 1.0;
    suffix[n] = 1.0;
  } else {
    prefix[0] = constant(1.0);
    suffix[n] = constant(1.0);
  }
  for (std::size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] * squares[k];
  for (std::size_t k = n; k-- > 0;) suffix[k] = squares[k] * suffix[k + 1];
  T numerator = weights_.w0 * prefix[n];
  T denominator = 0.0 * prefix[n];
  for (std::size_t i = 0; i < n; ++i) {
    const T others = prefix[i] * suffix[i + 1];
    numerator = numerator + weights_.w[i] * (r[i] * others);
    denominator = denominator + weights_.w[i] * others;
  }
  if (val(denominator) > 0.0) {
    const T q = numerator / denominator;
    if (finite(q)) return q;
  }
  // 0/0: two or more bounding functions vanish (or the products underflow). The mean of the ribbons of
  // the vanishing sides (of the two nearest ones when none is exactly zero) is finite and lies between
  // the one-sided limits.
  std::size_t first = 0, second = 1;  // the two smallest |B_j|
  if (std::abs(val(b[1])) < std::abs(val(b[0]))) std::swap(first, second);
  for (std::size_t j = 2; j < n; ++j) {
    const double m = std::abs(val(b[j]));
    if (m < std::abs(val(b[first]))) {
      second = first;
      first = j;
    } else if (m < std::abs(val(b[second]))) {
      second = j;
    }
  }
  T mean = r[first] + r[second];
  std::size_t count = 2;
  for (std::size_t j = 0; j < n; ++j) {
    if (j != first && j != second && val(b[j]) == 0.0) {
      mean = mean + r[j];
      ++count;
    }
  }
  return (1.0 / static_cast<double>(count)) * mean;
}

double IPatchSurface::value(const Vec3& p) const {
  // The same arithmetic as evaluate<double>, without heap allocations for n <= 32 (the hot path of
  // projection, sampling and the validity check).
  const std::size_t n = ribbons_.size();
  constexpr std::size_t kStack = 32;
  double stack[5 * (kStack + 1)];
  std::vector<double> heap;
  double* buffer = stack;
  if (n > kStack) {
    heap.resize(5 * (n + 1));
    buffer = heap.data();
  }
  double* r = buffer;
  double* b = r + (n + 1);
  double* squares = b + (n + 1);
  double* prefix = squares + (n + 1);
  double* suffix = prefix + (n + 1);
  for (std::size_t i = 0; i < n; ++i) {
    r[i] = ribbons_[i]->value(p);
    b[i] = bounds_[i]->value(p);
    squares[i] = b[i] * b[i];
  }
  prefix[0] = 1.0;
  suffix[n] = 1.0;
  for (std::size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] * squares[k];
  for (std::size_t k = n; k-- > 0;) suffix[k] = squares[k] * suffix[k + 1];
  double numerator = weights_.w0 * prefix[n], denominator = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double others = prefix[i] * suffix[i + 1];
    numerator += weights_.w[i] * (r[i] * others);
    denominator += weights_.w[i] * others;
  }
  if (denominator > 0.0) {
    const double q = numerator / denominator;
    if (std::isfinite(q)) return q;
  }
  return evaluate<double>(p);  // the 0/0 guard
}

ValueGradient IPatchSurface::value_gradient(const Vec3& p) const {
  const Jet j = evaluate<Jet>(p);
  return {j.v, j.g};
}

SecondOrder IPatchSurface::second_order(const Vec3& p) const {
  const Jet j = evaluate<Jet>(p);
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
