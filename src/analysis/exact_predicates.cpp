// Exact orientation signs with a floating-point filter (see exact_predicates.hpp).
#include "analysis/exact_predicates.hpp"

#include <array>
#include <cmath>
#include <cstddef>

namespace isopatch::exact {
namespace {

/// A number as a sum of doubles of increasing magnitude that do not overlap, without zeros. 192
/// components hold the largest value formed here (orient3d: three products of a two-component
/// difference with a 16-component minor, two components each).
struct Expansion {
  std::array<double, 192> component{};
  int size = 0;
};

/// x + y = a + b exactly, x = fl(a + b) (Knuth's two-sum).
void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double b_virtual = x - a;
  const double a_virtual = x - b_virtual;
  y = (a - a_virtual) + (b - b_virtual);
}

/// e += b exactly, in place (Shewchuk's Grow-Expansion with zero elimination).
void grow(Expansion& e, double b) {
  double q = b;
  int kept = 0;
  for (int i = 0; i < e.size; ++i) {
    double sum = 0.0, error = 0.0;
    two_sum(q, e.component[static_cast<std::size_t>(i)], sum, error);
    if (error != 0.0) e.component[static_cast<std::size_t>(kept++)] = error;
    q = sum;
  }
  if (q != 0.0) e.component[static_cast<std::size_t>(kept++)] = q;
  e.size = kept;
}

/// e += scale * (f_0 + f_1 + ...), exactly, for scale = +1 or -1.
void add(Expansion& e, const Expansion& f, double scale = 1.0) {
  for (int i = 0; i < f.size; ++i) grow(e, scale * f.component[static_cast<std::size_t>(i)]);
}

Expansion multiply(const Expansion& e, const Expansion& f) {
  Expansion h;
  for (int i = 0; i < e.size; ++i)
    for (int j = 0; j < f.size; ++j) {
      const double a = e.component[static_cast<std::size_t>(i)], b = f.component[static_cast<std::size_t>(j)];
      const double product = a * b;
      grow(h, std::fma(a, b, -product));  // a * b = product + this, exactly
      grow(h, product);
    }
  return h;
}

/// a - b exactly (at most two components).
Expansion difference(double a, double b) {
  Expansion e;
  grow(e, a);
  grow(e, -b);
  return e;
}

int sign(const Expansion& e) {
  if (e.size == 0) return 0;
  return e.component[static_cast<std::size_t>(e.size - 1)] > 0.0 ? 1 : -1;
}

int sign(double v) {
  return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
}

/// Relative bound on the rounding error of the double-precision determinants below (generous: the
/// analysis gives about 8 units in the last place of the permanent for orient3d, 3 for orient2d).
constexpr double kFilter = 1e-14;

}  // namespace

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double m0 = v.y() * w.z() - v.z() * w.y();
  const double m1 = v.z() * w.x() - v.x() * w.z();
  const double m2 = v.x() * w.y() - v.y() * w.x();
  const double det = u.x() * m0 + u.y() * m1 + u.z() * m2;
  const double permanent = std::abs(u.x()) * (std::abs(v.y() * w.z()) + std::abs(v.z() * w.y())) +
                           std::abs(u.y()) * (std::abs(v.z() * w.x()) + std::abs(v.x() * w.z())) +
                           std::abs(u.z()) * (std::abs(v.x() * w.y()) + std::abs(v.y() * w.x()));
  if (std::abs(det) > kFilter * permanent) return sign(det);
  // Every product of the permanent zero: a zero difference in each (no product of nonzero doubles
  // underflows, by the precondition), so each exact minor term is zero too. Coplanar neighbours on an
  // axis-aligned plane (a cap) and a shared vertex end here instead of in the expansions.
  if (permanent == 0.0) return 0;
  Expansion ue[3], ve[3], we[3];
  for (int i = 0; i < 3; ++i) {
    ue[i] = difference(b[i], a[i]);
    ve[i] = difference(c[i], a[i]);
    we[i] = difference(d[i], a[i]);
  }
  const auto minor = [&](int i, int j) {
    Expansion m = multiply(ve[i], we[j]);
    add(m, multiply(ve[j], we[i]), -1.0);
    return m;
  };
  Expansion exact = multiply(ue[0], minor(1, 2));
  add(exact, multiply(ue[1], minor(2, 0)));
  add(exact, multiply(ue[2], minor(0, 1)));
  return sign(exact);
}

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double left = (bx - ax) * (cy - ay);
  const double right = (by - ay) * (cx - ax);
  const double det = left - right;
  if (std::abs(det) > kFilter * (std::abs(left) + std::abs(right))) return sign(det);
  if (left == 0.0 && right == 0.0) return 0;  // a zero difference in each product (as orient3d)
  Expansion exact = multiply(difference(bx, ax), difference(cy, ay));
  add(exact, multiply(difference(by, ay), difference(cx, ax)), -1.0);
  return sign(exact);
}

}  // namespace isopatch::exact
