#pragma once
/// \file quadric.hpp
/// The ribbons and bounding functions of I-patches, all of them quadrics q(x) = x'Ax + b.x + c:
/// planes, Liming quadrics sigma (L1 L2 - lambda L3^2) (Liming 1944, as used by Sipos, Varady, Salvi &
/// Vaitkus, "Multi-sided implicit surfacing with I-patches", C&G 2020), rolling-ball cylinders of edge
/// blends (Varady & Rockwood 1997) and the conic cylinders lambda L3^2 - L1 L2 that bound smooth face
/// trimlines. One representation serves them all: exact value, gradient (2Ax + b) and Hessian (2A),
/// and sound interval bounds of f and grad f over a box (interval arithmetic, rounded outward).

#include <isopatch/surface.hpp>

#include <string>

namespace isopatch {

/// An affine function n.x + d; a plane with unit normal n when built by plane_through().
struct Affine {
  Vec3 n = Vec3::Zero();
  double d = 0.0;
  double operator()(const Vec3& x) const { return n.dot(x) + d; }
  Affine operator-() const { return {-n, -d}; }
};

/// The plane through `point` with normal direction `normal`, scaled to unit normal (a signed distance).
/// \throw InputError when `normal` is zero or not finite.
Affine plane_through(const Vec3& point, const Vec3& normal);

/// q(x) = x'Ax + b.x + c with A symmetric.
struct Quadric {
  Mat3 a = Mat3::Zero();
  Vec3 b = Vec3::Zero();
  double c = 0.0;

  double operator()(const Vec3& x) const { return x.dot(a * x) + b.dot(x) + c; }
  Vec3 gradient(const Vec3& x) const { return 2.0 * (a * x) + b; }

  static Quadric from(const Affine& f);
  /// f g, exactly.
  static Quadric product(const Affine& f, const Affine& g);
  Quadric operator*(double s) const { return {a * s, b * s, c * s}; }
  Quadric operator+(const Quadric& o) const { return {a + o.a, b + o.b, c + o.c}; }
  Quadric operator-(const Quadric& o) const { return {a - o.a, b - o.b, c - o.c}; }
};

/// sigma (l1 l2 - lambda l3^2): contains the lines l1 = l3 = 0 and l2 = l3 = 0 and touches l1 (l2) along
/// them; its trace on a plane across both lines is the conic tangent to the traces of l1 and l2.
Quadric liming_quadric(const Affine& l1, const Affine& l2, const Affine& l3, double lambda, double sigma);

/// The rolling-ball cylinder of radius r around the axis through `point` along unit `direction`:
/// (d(x)^2 - r^2) / (2r), d the distance to the axis; negative inside, |grad| = 1 on the surface.
/// \throw InputError when r <= 0 or the direction is zero.
Quadric ball_cylinder(const Vec3& point, const Vec3& direction, double r);

/// A quadric as a Surface, with exact derivatives and interval bounds.
class QuadricSurface final : public Surface {
 public:
  QuadricSurface(std::string name, Box box, Quadric q) : Surface(std::move(name), box), q_(q) {}
  double value(const Vec3& p) const override { return q_(p); }
  ValueGradient value_gradient(const Vec3& p) const override { return {q_(p), q_.gradient(p)}; }
  SecondOrder second_order(const Vec3& p) const override { return {q_(p), q_.gradient(p), 2.0 * q_.a}; }
  /// Interval arithmetic on the expanded polynomial: sound (rounded outward), exact for planes.
  std::optional<Interval> bound(const Box& box) const override;
  std::optional<IntervalGradient> gradient_bound(const Box& box) const override;
  const Quadric& quadric() const { return q_; }

 private:
  Quadric q_;
};

/// max(f, g) as a Surface: a union of the regions {f >= 0} and {g >= 0}, for bounding functions that a
/// single quadric cannot give (a face's corner region: inside a conic cylinder or beyond its chord).
/// Continuous, not smooth where f = g: the gradient and Hessian are those of the larger one (f on ties).
/// Bounds: the interval max of both bounds (sound), nullopt when either has none.
class MaxSurface final : public Surface {
 public:
  MaxSurface(std::string name, Box box, SurfacePtr f, SurfacePtr g);
  double value(const Vec3& p) const override;
  ValueGradient value_gradient(const Vec3& p) const override;
  SecondOrder second_order(const Vec3& p) const override;
  std::optional<Interval> bound(const Box& box) const override;
  std::optional<IntervalGradient> gradient_bound(const Box& box) const override;

 private:
  SurfacePtr f_, g_;
};

}  // namespace isopatch
