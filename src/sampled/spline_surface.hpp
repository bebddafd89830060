#pragma once
// The Surface interface of a tricubic B-spline, written once for every grid that holds one (dense
// coefficients: volume_surface.cpp; sparse ones around an OpenVDB grid's leaves: src/vdb). `Derived`
// provides `evaluate<Order>(p)` (value, with gradient, with Hessian at p) and `hull(box, gradient)`
// (convex-hull bounds over a box), and befriends this class when they are private.

#include <isopatch/surface.hpp>

#include <optional>

namespace isopatch::bspline {

template <class Derived>
class SplineSurface : public Surface {
 public:
  using Surface::Surface;

  double value(const Vec3& p) const override { return self().template evaluate<0>(p).value; }
  ValueGradient value_gradient(const Vec3& p) const override {
    const SecondOrder s = self().template evaluate<1>(p);
    return {s.value, s.gradient};
  }
  SecondOrder second_order(const Vec3& p) const override { return self().template evaluate<2>(p); }
  std::optional<Interval> bound(const Box& box) const override { return self().hull(box, false).value; }
  std::optional<IntervalGradient> gradient_bound(const Box& box) const override {
    return self().hull(box, true);
  }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace isopatch::bspline
