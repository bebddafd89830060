/// \file composite.cpp
/// Evaluation of the composite's boundary arcs (composite.hpp).
#include "composite_model/composite.hpp"

namespace isopatch {

Vec3 ConicArc::point(double t) const {
  if (t <= 0.0) return start;
  if (t >= 1.0) return end;
  // Bernstein weights of degree 2 with the middle one scaled by the arc's weight.
  const double a = (1.0 - t) * (1.0 - t);
  const double b = 2.0 * weight * t * (1.0 - t);
  const double c = t * t;
  return (a * start + b * control + c * end) / (a + b + c);
}

Vec3 side_start(const Composite& c, const PatchSide& side) {
  const ConicArc& a = c.curves[side.curve];
  return side.reversed ? a.end : a.start;
}

Vec3 side_end(const Composite& c, const PatchSide& side) {
  const ConicArc& a = c.curves[side.curve];
  return side.reversed ? a.start : a.end;
}

}  // namespace isopatch
