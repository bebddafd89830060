/// \file ipatch_surface.cpp
/// The I-patch function, its weights and its exact derivatives (ipatch_surface.hpp), in the library's
/// jets (autodiff.hpp).
#include "composite_model/ipatch_surface.hpp"

#include <isopatch/autodiff.hpp>
#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace isopatch {

namespace {

/// The Hessian of a jet as a matrix, and the upper triangle of a matrix as a jet's Hessian.
Mat3 hessian_matrix(const std::array<double, 6>& h) {
  Mat3 m;
  m << h[0], h[1], h[2], h[1], h[3], h[4], h[2], h[4], h[5];
  return m;
}
std::array<double, 6> upper_triangle(const Mat3& m) {
  return {m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)};
}

Vec3 vec(const std::array<double, 3>& g) {
  return {g[0], g[1], g[2]};
}

template <typename T>
T load(const Surface& s, const Vec3& p) {
  if constexpr (std::is_same_v<T, double>) {
    return s.value(p);
  } else if constexpr (std::is_same_v<T, GradientJet>) {
    const ValueGradient o = s.value_gradient(p);
    GradientJet j(o.value);
    j.g = {o.gradient.x(), o.gradient.y(), o.gradient.z()};
    return j;
  } else {
    const SecondOrder o = s.second_order(p);
    Jet j(o.value);
    j.g = {o.gradient.x(), o.gradient.y(), o.gradient.z()};
    j.h = upper_triangle(o.hessian);
    return j;
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
  } else {
    return x.finite();
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
  T product = T(1.0), numerator = T(0.0), denominator = T(0.0);
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
  const GradientJet j = evaluate<GradientJet>(p);
  return {j.v, vec(j.g)};
}

SecondOrder IPatchSurface::second_order(const Vec3& p) const {
  const Jet j = evaluate<Jet>(p);
  return {j.v, vec(j.g), hessian_matrix(j.h)};
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
