// Dense polylines with chord-length parameters; see polyline_curve.hpp.
#include "ngon/polyline_curve.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <utility>

namespace isopatch {

PolylineCurve::PolylineCurve(std::vector<Vec3> points) : points_(std::move(points)) {
  if (points_.size() < 2) throw InputError("polyline curve: need at least 2 points");
  // Cumulative lengths L_j first, then kappa_j = L_j / L.
  std::vector<double> knots(points_.size(), 0.0);
  for (std::size_t j = 1; j < points_.size(); ++j)
    knots[j] = knots[j - 1] + (points_[j] - points_[j - 1]).norm();
  length_ = knots.back();
  if (!(length_ > 0.0)) throw InputError("polyline curve: the polyline has zero length");
  for (double& k : knots) k /= length_;
  knots.back() = 1.0;  // exact, so point(1) is exactly the last point
  knots_ = std::move(knots);
}

Vec3 PolylineCurve::point(double u) const {
  if (!(u > 0.0)) return points_.front();
  if (u >= 1.0) return points_.back();
  // The first knot beyond u; the segment [j - 1, j] holds u and has positive knot span.
  const auto j = static_cast<std::size_t>(std::upper_bound(knots_.begin(), knots_.end(), u) - knots_.begin());
  const double t = (u - knots_[j - 1]) / (knots_[j] - knots_[j - 1]);
  return (1.0 - t) * points_[j - 1] + t * points_[j];
}

Vec3 PolylineCurve::start_derivative() const {
  // Skip repeated leading points (zero knot span) to the first segment of positive length.
  std::size_t j = 1;
  while (knots_[j] <= knots_[0]) ++j;
  return (points_[j] - points_[0]) / (knots_[j] - knots_[0]);
}

Vec3 PolylineCurve::end_derivative() const {
  const std::size_t last = points_.size() - 1;
  std::size_t j = last - 1;
  while (knots_[j] >= knots_[last]) --j;
  return (points_[last] - points_[j]) / (knots_[last] - knots_[j]);
}

}  // namespace isopatch
