#pragma once
/// \file callable_surface.hpp
/// Wraps a generic C++ callable `[](auto x, auto y, auto z) { ... }` as a Surface. The callable is
/// instantiated with double for values and with isopatch::Jet for exact gradients and Hessians
/// (forward-mode automatic differentiation, autodiff.hpp). Inside the callable, call math functions
/// unqualified (`sin(x)`) so that both instantiations resolve.

#include <isopatch/autodiff.hpp>
#include <isopatch/error.hpp>
#include <isopatch/surface.hpp>

#include <memory>
#include <string>
#include <utility>

namespace isopatch {

template <class F>
class CallableSurface final : public Surface {
 public:
  CallableSurface(F f, Box box, std::string name) : Surface(std::move(name), box), f_(std::move(f)) {}

  double value(const Vec3& p) const override { return static_cast<double>(f_(p.x(), p.y(), p.z())); }

  ValueGradient value_gradient(const Vec3& p) const override {
    const SecondOrder s = second_order(p);
    return {s.value, s.gradient};
  }

  SecondOrder second_order(const Vec3& p) const override {
    const Jet j = f_(Jet::variable(0, p.x()), Jet::variable(1, p.y()), Jet::variable(2, p.z()));
    SecondOrder s;
    s.value = j.v;
    s.gradient = Vec3(j.g[0], j.g[1], j.g[2]);
    s.hessian << j.h[0], j.h[1], j.h[2], j.h[1], j.h[3], j.h[4], j.h[2], j.h[4], j.h[5];
    return s;
  }

 private:
  F f_;
};

/// Makes a Surface from a callable f(x, y, z) (f < 0 inside) with default box `box`.
/// \throw InputError if `box` is not valid().
template <class F>
SurfacePtr make_surface(F f, const Box& box, std::string name = "callable") {
  if (!box.valid()) throw InputError("make_surface: the box must have lo < hi on every axis");
  return std::make_shared<CallableSurface<F>>(std::move(f), box, std::move(name));
}

}  // namespace isopatch
