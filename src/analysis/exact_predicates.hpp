#pragma once
// Exact orientation signs of points with double coordinates, after Shewchuk, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates" (Discrete Comput. Geom. 18, 1997):
// the determinant is evaluated in double precision first and its sign kept when it exceeds a bound on
// the rounding error; otherwise it is evaluated again exactly, as a floating-point expansion (a sum of
// non-overlapping doubles built with error-free sums and fused multiply-add products). Nearly
// coplanar or collinear points, which plain doubles classify at random, get their true sign.

#include <isopatch/geometry.hpp>

namespace isopatch::exact {

/// Sign (-1, 0, +1) of det[b - a; c - a; d - a]: +1 when d lies on the side of the plane through a, b,
/// c that (b - a) x (c - a) points to, 0 when the four points are coplanar. Exact for finite input
/// whose products do not overflow or underflow.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Sign of (bx - ax)(cy - ay) - (by - ay)(cx - ax): +1 when a, b, c turn counter-clockwise, 0 when they
/// are collinear. Exact as orient3d.
int orient2d(double ax, double ay, double bx, double by, double cx, double cy);

}  // namespace isopatch::exact
