#pragma once
/// \file interval_math.hpp
/// Sound interval arithmetic on Interval (Moore, Kearfott & Cloud, "Introduction to Interval
/// Analysis", SIAM 2009; conventions of IEEE Std 1788-2015).
///
/// Guarantee: for every operation F and points a in A (b in B), the result of F(A, B) contains the
/// exact value F(a, b) and the value the same floating-point operation computes. Endpoints are
/// computed in round-to-nearest and moved outward: one ulp for + - * / and sqrt (correctly rounded),
/// a few ulps for the libm functions. Rules:
///  - outside a function's domain, the result holds the values at the points where it is defined:
///    sqrt([-1, 4]) = [0, 2], log([0, 1]) = [-inf, 0]; no defined point gives an empty interval;
///  - division by an interval containing 0 gives the (unbounded) hull of the quotients;
///  - sin, cos, tan account for every period in the operand; pow(X, p) with non-integer p is defined
///    for x >= 0, with integer p for every x; pow(X, Y) covers negative bases at integer exponents;
///  - empty operands give empty results (min and max mirror std::min / std::max with NaN);
///  - signed zeros are not distinguished (-0 is taken as +0), and the few libm results that swallow
///    a NaN operand (pow(1, NaN) = 1, hypot(inf, NaN) = inf) are not tracked.

#include <isopatch/interval.hpp>

namespace isopatch {

Interval entire_interval();
Interval empty_interval();
/// The smallest interval holding both.
Interval hull(const Interval& a, const Interval& b);
Interval intersect(const Interval& a, const Interval& b);

Interval operator-(const Interval& a);
Interval operator+(const Interval& a, const Interval& b);
Interval operator-(const Interval& a, const Interval& b);
Interval operator*(const Interval& a, const Interval& b);
Interval operator/(const Interval& a, const Interval& b);

Interval sqr(const Interval& a);            ///< {x*x}: tight, unlike a*a
Interval powi(const Interval& a, int n);    ///< x^n by repeated squaring; n < 0 is 1/x^-n
Interval pow(const Interval& a, double p);  ///< std::pow(x, p)
Interval pow(const Interval& a, const Interval& b);
Interval sqrt(const Interval& a);
Interval exp(const Interval& a);
Interval log(const Interval& a);
Interval sin(const Interval& a);
Interval cos(const Interval& a);
Interval tan(const Interval& a);
Interval asin(const Interval& a);
Interval acos(const Interval& a);
Interval atan(const Interval& a);
Interval sinh(const Interval& a);
Interval cosh(const Interval& a);
Interval tanh(const Interval& a);
Interval abs(const Interval& a);
Interval min(const Interval& a, const Interval& b);  ///< {b < a ? b : a}
Interval max(const Interval& a, const Interval& b);  ///< {a < b ? b : a}
Interval hypot(const Interval& a, const Interval& b);
Interval atan2(const Interval& y, const Interval& x);

}  // namespace isopatch
