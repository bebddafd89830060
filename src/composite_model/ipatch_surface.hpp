#pragma once
/// \file ipatch_surface.hpp
/// The n-sided I-patch of Varady, Benko, Kos & Rockwood (2001), in the normalized form that Sipos,
/// Varady, Salvi & Vaitkus (C&G 2020) evaluate: with ribbons R_i, bounding functions B_i, weights
/// w_i > 0 and w_0,
///
///          sum_i w_i R_i prod_{j!=i} B_j^2  +  w_0 prod_j B_j^2
///   F(x) = ----------------------------------------------------
///                    sum_i w_i prod_{j!=i} B_j^2
///
/// The numerator alone is the plain I-patch I(x); the denominator is positive wherever at most one B_j
/// vanishes, so F and I have the same sign there. Where B_i = 0 (and no other B_j) F = R_i and
/// grad F = grad R_i: G1 contact with every ribbon along the whole bounding surface.

#include <isopatch/surface.hpp>

#include <string>
#include <vector>

namespace isopatch {

/// The weights of an I-patch: w[i] > 0 per side, and w0 (any sign).
struct IPatchWeights {
  std::vector<double> w;
  double w0 = 0.0;
};

/// Rule A of Sipos et al. (the default of their code): with a reference point c inside the region and
/// factors d_i > 0 (empty = all 1), w_i = d_i B_i(c)^2 / |R_i(c)| and w_0 = -sum_i d_i sign(R_i(c)), so
/// that F(c) = 0: the patch passes through c. The zero set does not change when a ribbon or a bounding
/// function is scaled by a positive factor.
/// \throw InputError (naming `patch`) when some B_j(c) <= 0 (c outside the region), some R_i(c) = 0,
///        the R_i(c) differ in sign (the weights would be erratic and give extra sheets), d has the
///        wrong size or a non-positive or non-finite entry.
IPatchWeights rule_a_weights(const std::vector<SurfacePtr>& ribbons, const std::vector<SurfacePtr>& bounds,
                             const Vec3& centre, const std::vector<double>& d, const std::string& patch);

/// An I-patch as a Surface. Exact value, gradient and Hessian (forward differentiation of the product
/// form, accumulated side by side: O(n) per point, no allocation). Never NaN for finite input: where
/// the denominator vanishes (two or more B_j = 0, e.g. at the corners, where F has a direction-
/// dependent limit) F is the mean of the ribbons whose B_j vanish, and so are its derivatives.
/// bound() and gradient_bound() are nullopt: the quotient's denominator is an interval containing 0
/// on any box that touches two bounding surfaces, so no useful sound bound exists there.
class IPatchSurface final : public Surface {
 public:
  /// \throw InputError when the sizes differ, n < 2, or a weight is not finite or w_i <= 0.
  IPatchSurface(std::string name, Box box, std::vector<SurfacePtr> ribbons, std::vector<SurfacePtr> bounds,
                IPatchWeights weights);

  double value(const Vec3& p) const override;
  ValueGradient value_gradient(const Vec3& p) const override;
  SecondOrder second_order(const Vec3& p) const override;

  /// The plain (unnormalized) I-patch: the numerator above. Zero, with zero gradient, wherever two
  /// B_j vanish: never mesh it, it is for comparisons.
  double plain_value(const Vec3& p) const;
  /// min_j B_j(p): the point is in the patch's region when this is >= 0.
  double region_margin(const Vec3& p) const;

  std::size_t sides() const { return ribbons_.size(); }
  const std::vector<SurfacePtr>& ribbons() const { return ribbons_; }
  const std::vector<SurfacePtr>& bounds() const { return bounds_; }
  const IPatchWeights& weights() const { return weights_; }

 private:
  template <typename T>
  T evaluate(const Vec3& p) const;

  std::vector<SurfacePtr> ribbons_;
  std::vector<SurfacePtr> bounds_;
  IPatchWeights weights_;
};

}  // namespace isopatch
