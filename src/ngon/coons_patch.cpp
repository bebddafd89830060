// The multi-sided C0 Coons patch (Salvi 2020, arXiv:2002.11347); see coons_patch.hpp. The formulas
// below use the paper's indices: C_i on domain side [V_{i-1}, V_i], corner P_i = C_i(0) at V_{i-1}.
#include "ngon/coons_patch.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <string>
#include <utility>

#include "core/cyclic.hpp"

namespace isopatch {
namespace {

/// Below this, h_i = lambda_{i-1} + lambda_i is treated as 0: ribbon i is then far from its side and
/// its weight h_i / 2 vanishes, so any s_i will do (the paper's code takes 1/2, docs/algorithms.md 3.5.3).
constexpr double kSideParameterEps = 1e-12;

Vec3 cubic_bezier(const std::array<Vec3, 4>& c, double u) {
  const double v = 1.0 - u;
  return v * v * v * c[0] + 3.0 * v * v * u * c[1] + 3.0 * v * u * u * c[2] + u * u * u * c[3];
}

}  // namespace

CoonsPatch::CoonsPatch(std::vector<PolylineCurve> curves)
    : curves_(std::move(curves)), domain_(static_cast<int>(curves_.size())) {
  double longest = 0.0;
  for (const PolylineCurve& c : curves_) longest = std::max(longest, c.length());
  for (std::size_t k = 0; k < curves_.size(); ++k) {
    const std::size_t k1 = next(k, curves_.size());
    if ((curves_[k].back() - curves_[k1].front()).norm() > 1e-9 * longest)
      throw InputError("Coons patch: curve " + std::to_string(k) + " does not end where curve " +
                       std::to_string(k1) + " starts");
  }
}

const PolylineCurve& CoonsPatch::paper_curve(int i) const {
  return curves_[static_cast<std::size_t>(domain_.wrap(i - 1))];
}

Vec3 CoonsPatch::opposite(int i, double u) const {
  const Vec3& from = paper_curve(i + 2).front();  // P_{i+2}
  const Vec3& to = paper_curve(i - 1).front();    // P_{i-1}
  // For n = 3 the opposite "side" is the single corner P_{i-1} = P_{i+2}.
  if (sides() == 3) return to;
  // The cubic leaves P_{i+2} along C_{i+2} and arrives at P_{i-1} along C_{i-2}, both derivatives taken
  // from the polylines' knots.
  const std::array<Vec3, 4> control{from, from + paper_curve(i + 2).start_derivative() / 3.0,
                                    to - paper_curve(i - 2).end_derivative() / 3.0, to};
  return cubic_bezier(control, u);
}

Vec3 CoonsPatch::ribbon(int i, double s, double d) const {
  s = std::clamp(s, 0.0, 1.0);
  d = std::clamp(d, 0.0, 1.0);
  const Vec3& p_i = paper_curve(i).front();
  const Vec3& p_next = paper_curve(i + 1).front();
  const Vec3& p_prev = paper_curve(i - 1).front();
  const Vec3& p_opposite = paper_curve(i + 2).front();
  // A bilinearly blended Coons patch whose sides are C_i (d = 0), C_{i-1} reversed (s = 0), C_{i+1}
  // (s = 1) and D_i reversed (d = 1), minus the bilinear interpolant of its four corners.
  const Vec3 sides_sum = (1.0 - d) * paper_curve(i).point(s) + d * opposite(i, 1.0 - s) +
                         (1.0 - s) * paper_curve(i - 1).point(1.0 - d) + s * paper_curve(i + 1).point(d);
  const Vec3 corners =
      (1.0 - s) * (1.0 - d) * p_i + s * (1.0 - d) * p_next + (1.0 - s) * d * p_prev + s * d * p_opposite;
  return sides_sum - corners;
}

void CoonsPatch::ribbon_weights(std::span<const double> lambda, std::span<double> weights) {
  const std::size_t n = lambda.size();
  for (std::size_t i = 0; i < n; ++i) weights[i] = 0.5 * (lambda[(i + n - 1) % n] + lambda[i]);
}

Vec3 CoonsPatch::evaluate(std::span<const double> lambda) const {
  const int n = sides();
  Vec3 p = Vec3::Zero();
  for (int i = 0; i < n; ++i) {
    const double lambda_prev = lambda[static_cast<std::size_t>(domain_.wrap(i - 1))];
    const double lambda_i = lambda[static_cast<std::size_t>(i)];
    const double h = lambda_prev + lambda_i;  // 1 on the ribbon's own side, 0 on the far sides
    if (h <= 0.0) continue;                   // weight 0
    const double s = h < kSideParameterEps ? 0.5 : lambda_i / h;
    p += 0.5 * h * ribbon(i, s, 1.0 - h);
  }
  return p;
}

}  // namespace isopatch
