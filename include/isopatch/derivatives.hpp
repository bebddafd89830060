#pragma once
/// \file derivatives.hpp
/// What an evaluation of f returns beyond its value: f with its exact gradient, f with gradient and
/// Hessian at one point, and interval bounds of f and of its gradient over a box. Plain value types,
/// shared by the expression evaluators (expression.hpp) and the Surface interface (surface.hpp),
/// which includes this header.

#include <isopatch/geometry.hpp>
#include <isopatch/interval.hpp>

#include <array>

namespace isopatch {

/// f and its gradient at one point.
struct ValueGradient {
  double value = 0.0;
  Vec3 gradient = Vec3::Zero();
};

/// f, its gradient and its (symmetric) Hessian at one point.
struct SecondOrder {
  double value = 0.0;
  Vec3 gradient = Vec3::Zero();
  Mat3 hessian = Mat3::Zero();
};

/// Interval bounds of f and of its gradient over a box.
struct IntervalGradient {
  Interval value;
  std::array<Interval, 3> gradient;
};

/// Interval bounds of f, its gradient and its Hessian over a box. The Hessian's six entries are
/// xx, xy, xz, yy, yz, zz; an entry is the whole line where it is unbounded or where the gradient may
/// jump inside the box (a kink of min, max or abs).
struct IntervalHessian {
  Interval value;
  std::array<Interval, 3> gradient;
  std::array<Interval, 6> hessian;
};

}  // namespace isopatch
