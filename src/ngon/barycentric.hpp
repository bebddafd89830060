#pragma once
/// \file barycentric.hpp
/// Generalized barycentric coordinates on the regular n-gon domain: the three-point family of
/// M. S. Floater, K. Hormann, G. Kós, "A general construction of barycentric coordinates over convex
/// polygons", Adv. Comput. Math. 24 (2006) 311-331, with p = 0 (Wachspress: E. L. Wachspress, "A
/// Rational Finite Element Basis", 1975) and p = 1 (mean value: M. S. Floater, "Mean value
/// coordinates", CAGD 20 (2003) 19-27). They are the lambda_i of Sipos & Salvi 2021, eq. (1).

#include "ngon/domain.hpp"

#include <span>

namespace isopatch {

/// Which member of the three-point family to use.
enum class CoordinateKind {
  Wachspress,  ///< p = 0: rational, cheap, exactly bilinear on the n = 4 square (the default)
  MeanValue,   ///< p = 1: smooth, positive, differs from Wachspress for n >= 5
};

/// Writes lambda_0 .. lambda_{n-1} of the point x for the domain's vertices V_0 .. V_{n-1}.
///
/// \pre lambda.size() == domain.sides(); x lies in the closed domain (points a rounding error outside
///      are fine: the formulas extend continuously, and coordinates may then be slightly negative).
/// Guarantees, up to rounding (about 1e-15 relative): sum lambda_k = 1; sum lambda_k V_k = x (linear
/// precision); lambda_k >= 0 inside. On side k at parameter t, lambda_k = 1 - t, lambda_{k+1} = t and
/// every other coordinate is 0 (to rounding of x itself). At a vertex V_k (|x - V_k| <= 1e-14) the
/// result is exactly the unit vector e_k.
///
/// Evaluated in the division-free product form (weights multiplied by prod_j A_j, A_j = area(x, V_j,
/// V_{j+1})), so it stays finite and accurate on and near the boundary; see barycentric.cpp.
void barycentric_coordinates(const Domain& domain, const Vec2& x, CoordinateKind kind,
                             std::span<double> lambda);

/// Distance from a vertex below which barycentric_coordinates() returns that vertex's unit vector.
inline constexpr double kBarycentricVertexTolerance = 1e-14;

}  // namespace isopatch
