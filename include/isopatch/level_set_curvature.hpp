#pragma once
/// \file level_set_curvature.hpp
/// Exact curvature of the level set of f through a point, from f's first and second derivatives, and
/// the edge length that keeps a chordal error bound on a surface of given curvature. Discrete
/// curvature of a mesh and per-vertex curvature fields are in curvature.hpp (which includes this).
///
/// Sign convention: with f < 0 inside and outward normals, a sphere of radius R has H = +1/R and
/// K = 1/R^2.

#include <isopatch/derivatives.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

namespace isopatch {

/// Curvatures at one point: H = (k1 + k2) / 2 and K = k1 k2.
struct PointCurvature {
  double mean = 0.0;
  double gaussian = 0.0;
};

/// Exact curvature of the level set through the sample point (Goldman 2005, "Curvature formulas for
/// implicit curves and surfaces"): with g = grad f and Hf the Hessian,
/// H = (|g|^2 tr(Hf) - g^T Hf g) / (2 |g|^3) and K = g^T adj(Hf) g / |g|^4.
/// Both are invariant under f -> phi(f) with phi' > 0. Returns NaNs where g = 0 (singular point).
PointCurvature analytic_curvature(const SecondOrder& sample);
/// Same, evaluating surface.second_order(p).
PointCurvature analytic_curvature(const Surface& surface, const Vec3& p);
/// Largest absolute principal curvature max(|k1|, |k2|) = |H| + sqrt(max(H^2 - K, 0)) of the level set
/// through p; +infinity where the gradient vanishes or the derivatives are not finite.
double max_abs_principal_curvature(const Surface& surface, const Vec3& p);

/// The edge length whose equilateral triangles on a surface of largest principal curvature
/// `max_abs_curvature` keep their centroids within `max_error` of the surface, with room for edges up
/// to 4/3 of it (the remesher's tolerance): sqrt(3 * max_error / kappa). Infinite when the curvature is
/// zero. \pre max_error > 0, max_abs_curvature >= 0.
double size_for_error(double max_abs_curvature, double max_error);

}  // namespace isopatch
