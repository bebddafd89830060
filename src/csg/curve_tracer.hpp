#pragma once
/// \file curve_tracer.hpp
/// Tracing the curve where two smooth functions vanish together (a crease f_i = f_j = 0, or a seam
/// f_i = 0 on a plane) by predictor-corrector continuation: a step along the tangent grad a x grad b,
/// then minimum-norm Newton back onto both functions (surface/curve_point.hpp), the step halved until
/// the tangent turns by at most a set angle (Allgower & Georg 2003, ch. 6). The trace ends where the
/// curve closes on its start, leaves the part of the shape it belongs to (a corner, found by Newton on
/// three functions), leaves the box, or cannot be followed.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <functional>
#include <vector>

namespace isopatch {

/// Why a trace ended.
enum class TraceEnd {
  Closed,  ///< back at its start: a closed loop (the last point is the start again)
  Corner,  ///< at a point where a third function vanishes too (`corner`, `third` set)
  Box,     ///< it left the box
  Lost,    ///< no step, however short, stays on the curve (a tangential contact or a cusp)
};

/// A traced curve.
struct TracedPath {
  std::vector<Vec3> points;  ///< from the start, on both functions
  TraceEnd end = TraceEnd::Lost;
  int third = -1;  ///< Corner: the face that takes over
};

/// What the tracer needs to know beyond the two functions.
struct TraceParams {
  double step = 0.0;       ///< longest step (> 0)
  double tolerance = 0.0;  ///< Newton tolerance (|g| / |grad g|)
  Box box;                 ///< the trace ends where it leaves this box
  std::size_t max_points = 100000;
  /// The face that owns a point of the curve: -1 while the point still belongs to the curve, else the
  /// face that takes over there (whose function `third_function` returns).
  std::function<int(const Vec3&)> owner;
  std::function<const Surface&(int)> third_function;
  /// Points known to lie on the curve where it must end (a seam's crossings with the creases around
  /// its piece): the trace ends at the first one a step passes (within a thousandth of the step), with
  /// TraceEnd::Corner and `third` -1.
  std::vector<Vec3> targets;
};

/// Traces a = b = 0 from `start` (on both) in the direction of `sign` * (grad a x grad b).
TracedPath trace_curve(const Surface& a, const Surface& b, const Vec3& start, double sign,
                       const TraceParams& params);

/// The unit tangent grad a x grad b at p (zero when the gradients are parallel).
Vec3 curve_tangent(const Surface& a, const Surface& b, const Vec3& p);

}  // namespace isopatch
