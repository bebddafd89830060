#pragma once
/// \file coons_patch.hpp
/// The multi-sided C0 Coons patch of P. Salvi, "A multi-sided generalization of the C0 Coons patch",
/// WAIT 2020, arXiv:2002.11347 (formulas in docs/algorithms.md 3.5.3), over n boundary curves given as dense
/// polylines (polyline_curve.hpp). It interpolates every boundary curve, so the base of an n-sided
/// patch starts on the traced face curves instead of on their chords (Sipos & Salvi 2021, sec. 2.2).
///
/// Our indexing (domain.hpp): curve k runs from corner k (at V_k) to corner k + 1 (at V_{k+1}) along
/// domain side k. The paper puts C_i on the side [V_{i-1}, V_i], so its C_i is our curve i - 1; the
/// conversion lives in CoonsPatch::paper_curve() alone, and coons_patch.cpp writes the formulas with
/// the paper's indices. Both conventions index lambda by domain vertex, so lambda needs no conversion.

#include <span>
#include <vector>

#include "ngon/base_surface.hpp"
#include "ngon/domain.hpp"
#include "ngon/polyline_curve.hpp"

namespace isopatch {

class CoonsPatch final : public BaseSurface {
 public:
  /// \param curves  n = 3..16 curves in our indexing; curve k must end where curve k + 1 starts.
  /// \throw InputError unless 3 <= n <= 12 and consecutive curves share their end points (to 1e-9 of
  ///        the longest curve).
  explicit CoonsPatch(std::vector<PolylineCurve> curves);

  int sides() const override { return static_cast<int>(curves_.size()); }
  /// S(x) = sum_i R_i(s_i, d_i) (lambda_{i-1} + lambda_i) / 2. On side k at parameter t (lambda_k =
  /// 1 - t, lambda_{k+1} = t, others 0) it equals curve k at u = t.
  /// \pre lambda.size() == sides(), sum lambda = 1, lambda >= 0 (up to rounding).
  Vec3 evaluate(std::span<const double> lambda) const override;

  /// The ribbon weights (lambda_{i-1} + lambda_i) / 2 in the paper's ribbon order i = 0..n-1; they sum to
  /// 1 whenever the lambdas do.
  static void ribbon_weights(std::span<const double> lambda, std::span<double> weights);

 private:
  /// The paper's C_i (for any integer i, taken mod n): our curve i - 1. THE index conversion.
  const PolylineCurve& paper_curve(int i) const;
  /// The paper's ribbon R_i at (s, d) in [0, 1]^2 (clamped).
  Vec3 ribbon(int i, double s, double d) const;
  /// The paper's opposite curve D_i at u, joining P_{i+2} (u = 0) to P_{i-1} (u = 1).
  Vec3 opposite(int i, double u) const;

  std::vector<PolylineCurve> curves_;
  Domain domain_;
};

}  // namespace isopatch
