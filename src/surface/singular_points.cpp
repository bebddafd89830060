// Singular points of f = 0 by interval subdivision and Gauss-Newton: see singular_points.hpp.
#include <isopatch/error.hpp>
#include <isopatch/interval_math.hpp>
#include <isopatch/singular_points.hpp>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "surface/singular_components.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace isopatch {
namespace {

/// The smallest box is this fraction of the box's longest side by default.
constexpr double kDefaultBoxFraction = 1.0 / 256.0;
/// Gauss-Newton steps per run, and halvings of a step that does not lower the residual.
constexpr int kMaxSteps = 60;
constexpr int kMaxHalvings = 8;
/// Singular values of the Jacobian below this fraction of the largest are dropped (truncated
/// pseudo-inverse): the direction along a curve of solutions, and rounding at a cusp.
constexpr double kSingularValueCut = 1e-10;
/// A run stops after a step shorter than this fraction of its start box: the point is then within about
/// that much of the solution even where Gauss-Newton converges only linearly (into a cusp).
constexpr double kSmallStep = 1e-8;
/// Krawczyk's test is tried once more on the box grown by this fraction of its sides on every side when
/// its operator is narrower than kContracting of the box but does not fit in it.
constexpr double kGrow = 1.0 / 8.0;
constexpr double kContracting = 0.5;
/// A Hessian whose eigenvalues differ by more than this ratio is singular for Krawczyk's test.
constexpr double kSingularHessian = 1e-8;

bool finite(const SecondOrder& s) {
  return std::isfinite(s.value) && s.gradient.allFinite() && s.hessian.allFinite();
}

/// The entry (i, j) of an IntervalHessian's six.
const Interval& hessian_entry(const IntervalHessian& h, int i, int j) {
  static constexpr int kIndex[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
  return h.hessian[static_cast<std::size_t>(kIndex[i][j])];
}

bool excludes_zero(const Interval& v) {
  return !v.empty() && !v.contains_zero();
}

/// What the enclosures say about a box.
enum class Verdict {
  Excluded,   ///< no point of the box has f = 0 and grad f = 0
  Unique,     ///< grad f has exactly one zero in the box (Krawczyk): Gauss-Newton from it, no split
  Undecided,  ///< split further, or refine from it at the smallest size
};

/// `box` grown about its centre by `fraction` of its sides on every side.
Box grown_box(const Box& box, double fraction) {
  const Vec3 margin = fraction * box.size();
  return Box{box.lo - margin, box.hi + margin};
}

/// (region - c) for the centre c of `box`, per axis.
std::array<Interval, 3> offsets(const Box& box, const Box& region) {
  const Vec3 c = box.centre();
  std::array<Interval, 3> d;
  for (int i = 0; i < 3; ++i)
    d[static_cast<std::size_t>(i)] = Interval{region.lo[i] - c[i], region.hi[i] - c[i]};
  return d;
}

/// The Krawczyk operator for grad f = 0 on `region`, a box about the centre c of `box` holding it
/// (Krawczyk 1969; Moore, Kearfott & Cloud 2009, 8.2): K = c - Y grad f(c) + (I - Y H(region))
/// (region - c), with `h` the enclosures over `region`, `at` those at c and Y the inverse of the
/// Hessian at c. Every zero of grad f in `region` lies in K, so K missing `box` on an axis excludes
/// `box`; K inside the interior of `region` proves exactly one zero there, so `box` holds at most one (a
/// nondegenerate critical point: a node such as the Barth surfaces' or a cone's apex) and needs no
/// further split. Undecided otherwise, also when an entry of H(region) is unbounded; `*spread` is then
/// the largest width of K relative to the region's (below 1 when K contracts).
Verdict krawczyk(const Box& box, const Box& region, const Mat3& y, const IntervalGradient& at,
                 const IntervalHessian& h, double* spread) {
  *spread = std::numeric_limits<double>::infinity();
  for (const Interval& e : h.hessian)
    if (e.empty() || !std::isfinite(e.lo) || !std::isfinite(e.hi)) return Verdict::Undecided;
  const Vec3 c = box.centre();
  const std::array<Interval, 3> d = offsets(box, region);
  bool inside = true;
  double widest = 0.0;
  for (int i = 0; i < 3; ++i) {
    Interval k{c[i], c[i]};
    for (int j = 0; j < 3; ++j) {
      k = k - Interval{y(i, j), y(i, j)} * at.gradient[static_cast<std::size_t>(j)];
      Interval m{i == j ? 1.0 : 0.0, i == j ? 1.0 : 0.0};  // (I - Y H(region))_ij
      for (int l = 0; l < 3; ++l) m = m - Interval{y(i, l), y(i, l)} * hessian_entry(h, l, j);
      k = k + m * d[static_cast<std::size_t>(j)];
    }
    if (k.empty()) return Verdict::Undecided;
    if (k.hi < box.lo[i] || k.lo > box.hi[i]) return Verdict::Excluded;
    if (!(k.lo > region.lo[i] && k.hi < region.hi[i])) inside = false;
    widest = std::max(widest, k.width() / (region.hi[i] - region.lo[i]));
  }
  if (inside) return Verdict::Unique;
  *spread = widest;
  return Verdict::Undecided;
}

/// What the enclosures prove about `box` (see Verdict): Excluded only when an enclosure proves that
/// f = 0 and grad f = 0 hold nowhere in it. In order of cost: the surface's own (natural) enclosures of
/// f and grad f; the first-order centred form f(c) + grad f(box) . (box - c) about the centre c; when the
/// surface bounds its Hessian, the mean value form of grad f, grad f(c) + H(box) (box - c), and the
/// second-order form of f, f(c) + grad f(c) . (box - c) + (box - c)^T H(box) (box - c) / 2 (Moore 1966,
/// centred forms); Krawczyk's test (krawczyk). The values at c are themselves enclosures (the
/// surface's bound of the box [c, c]), so rounding is covered. The natural enclosure of a polynomial in the
/// power basis (the Chmutov surface's Chebyshev polynomials, the Barth surfaces' products) overestimates by a
/// constant factor however small the box, the centred forms by O(w^2): they are what lets the subdivision
/// stop near the surface away from singular points.
Verdict examine(const Surface& surface, const Box& box) {
  const std::optional<IntervalGradient> b = surface.gradient_bound(box);
  if (!b) return Verdict::Undecided;
  if (b->value.empty()) return Verdict::Excluded;  // f is NaN on the whole box
  if (excludes_zero(b->value)) return Verdict::Excluded;
  for (const Interval& g : b->gradient)
    if (excludes_zero(g)) return Verdict::Excluded;
  const Vec3 c = box.centre();
  const std::optional<IntervalGradient> at = surface.gradient_bound(Box{c, c});
  if (!at || at->value.empty()) return Verdict::Undecided;
  std::array<Interval, 3> d;  // box - c
  for (int i = 0; i < 3; ++i) {
    const double r = 0.5 * (box.hi[i] - box.lo[i]);
    d[static_cast<std::size_t>(i)] = Interval{-r, r};
  }
  Interval first = at->value;  // f(c) + grad f(box) . (box - c)
  for (std::size_t i = 0; i < 3; ++i) first = first + b->gradient[i] * d[i];
  if (excludes_zero(first)) return Verdict::Excluded;
  const std::optional<IntervalHessian> h = surface.hessian_bound(box);
  if (!h) return Verdict::Undecided;
  Interval second = at->value;  // f(c) + grad f(c) . (box - c) + (box - c)^T H (box - c) / 2
  const Interval half{0.5, 0.5};
  for (int i = 0; i < 3; ++i) {
    const auto si = static_cast<std::size_t>(i);
    Interval gradient = at->gradient[si];  // grad f(c)_i + H_i. (box - c)
    for (int j = 0; j < 3; ++j)
      gradient = gradient + hessian_entry(*h, i, j) * d[static_cast<std::size_t>(j)];
    if (excludes_zero(gradient)) return Verdict::Excluded;
    second = second + at->gradient[si] * d[si] + half * hessian_entry(*h, i, i) * sqr(d[si]);
    for (int j = i + 1; j < 3; ++j)
      second = second + hessian_entry(*h, i, j) * d[si] * d[static_cast<std::size_t>(j)];
  }
  if (excludes_zero(second)) return Verdict::Excluded;
  for (const Interval& e : h->hessian)
    if (e.empty() || !std::isfinite(e.lo) || !std::isfinite(e.hi)) return Verdict::Undecided;
  // Krawczyk's operator can contract only where H(box) is narrow next to the Hessian's smallest
  // eigenvalue at c: elsewhere (a cusp, a curve of critical points, a box still large) it is skipped.
  const SecondOrder sc = surface.second_order(c);
  if (!finite(sc)) return Verdict::Undecided;
  Eigen::SelfAdjointEigenSolver<Mat3> eigen;
  eigen.computeDirect(sc.hessian, Eigen::EigenvaluesOnly);
  const Vec3 sigma = eigen.eigenvalues().cwiseAbs();
  if (!(sigma.minCoeff() > kSingularHessian * sigma.maxCoeff())) return Verdict::Undecided;
  for (int i = 0; i < 3; ++i) {
    double row = 0.0;
    for (int j = 0; j < 3; ++j) row += hessian_entry(*h, i, j).width();
    if (!(row < sigma.minCoeff())) return Verdict::Undecided;
  }
  const Mat3 y = sc.hessian.inverse();
  double spread = 0.0;
  const Verdict verdict = krawczyk(box, box, y, *at, *h, &spread);
  if (verdict != Verdict::Undecided || !(spread < kContracting)) return verdict;
  // K contracts but does not fit: the zero may lie on a face of the box (a split plane through it, as
  // x = 0 through the Barth surfaces' nodes). Once more on the box grown by kGrow of its sides.
  const Box grown = grown_box(box, kGrow);
  const std::optional<IntervalHessian> hg = surface.hessian_bound(grown);
  if (!hg) return Verdict::Undecided;
  return krawczyk(box, grown, y, *at, *hg, &spread);
}

/// The two halves of `box` across its longest side.
std::array<Box, 2> split(const Box& box) {
  const Vec3 size = box.size();
  int axis = 0;
  if (size.y() > size[axis]) axis = 1;
  if (size.z() > size[axis]) axis = 2;
  const double middle = 0.5 * (box.lo[axis] + box.hi[axis]);
  Box low = box, high = box;
  low.hi[axis] = middle;
  high.lo[axis] = middle;
  return {low, high};
}

using Residual = Eigen::Matrix<double, 4, 1>;
using Jacobian = Eigen::Matrix<double, 4, 3>;

/// (f / L, f_x, f_y, f_z): f divided by a length L so that every equation has the units of grad f. L is
/// the searched box's size, much more than the distance to a solution, so the f row weighs little until
/// grad f is nearly 0: near a curve of solutions (two sheets crossing, where f = O(d^2) and its
/// linearization is poor) a heavier f row turned the steps along the curve and out of the start box.
Residual residual(const SecondOrder& s, double length) {
  Residual r;
  r << s.value / length, s.gradient;
  return r;
}

/// The largest |grad f| at the corners of `box` (0 when none is finite).
double corner_gradient_scale(const Surface& surface, const Box& box) {
  double scale = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c((corner & 1) ? box.hi.x() : box.lo.x(), (corner & 2) ? box.hi.y() : box.lo.y(),
                 (corner & 4) ? box.hi.z() : box.lo.z());
    const double g = surface.value_gradient(c).gradient.norm();
    if (std::isfinite(g)) scale = std::max(scale, g);
  }
  return scale;
}

/// Gauss-Newton from the centre of `start` on f = f_x = f_y = f_z = 0 (the residual() of `length_scale`,
/// steps by the pseudo-inverse of the Jacobian [grad f / L; Hessian] without its singular values under
/// kSingularValueCut of the largest, at most the start box's longest side w long, halved until the
/// residual decreases), given up as soon as it leaves `start` grown by w, and accepted as described for
/// SingularSearchSettings::tolerance (G from corner_gradient_scale); nothing when it fails, leaves, or
/// does not reach the tolerance.
std::optional<singular::Converged> refine(const Surface& surface, const Box& start, double length_scale,
                                          double tolerance) {
  const double w = start.size().maxCoeff();
  Vec3 p = start.centre();
  SecondOrder s = surface.second_order(p);
  if (!finite(s)) return std::nullopt;
  for (int step = 0; step < kMaxSteps; ++step) {
    const Residual r = residual(s, length_scale);
    const double norm = r.norm();
    if (norm == 0.0) break;
    Jacobian j;
    j.row(0) = s.gradient.transpose() / length_scale;
    j.bottomRows<3>() = s.hessian;
    const Eigen::JacobiSVD<Jacobian> svd(j, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Vector3d sigma = svd.singularValues();
    if (!(sigma[0] > 0.0)) break;
    const Eigen::Vector3d ur = svd.matrixU().leftCols<3>().transpose() * r;
    Eigen::Vector3d coefficients = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      if (sigma[k] > kSingularValueCut * sigma[0]) coefficients[k] = -ur[k] / sigma[k];
    Vec3 move = svd.matrixV() * coefficients;
    const double length = move.norm();
    if (!(length > 0.0)) break;
    if (length > w) move *= w / length;  // at most one box size per step
    bool lower = false;
    for (int halving = 0; halving <= kMaxHalvings; ++halving) {
      const Vec3 q = p + move;
      if (!start.contains(q, w)) return std::nullopt;  // it would not be kept: stop now
      const SecondOrder t = surface.second_order(q);
      if (finite(t) && residual(t, length_scale).norm() < norm) {
        lower = true;
        p = q;
        s = t;
        break;
      }
      move *= 0.5;
    }
    if (!lower || move.norm() <= kSmallStep * w) break;  // as close as rounding allows, or close enough
  }
  const double gradient = s.gradient.norm();
  const double scale = corner_gradient_scale(surface, start);
  if (!(scale > 0.0) || !(gradient <= tolerance * scale) || !(std::abs(s.value) <= tolerance * scale * w))
    return std::nullopt;
  return singular::Converged{p, gradient / scale, 0};
}

void check_settings(const Box& box, const SingularSearchSettings& s) {
  if (!box.valid()) throw InputError("the box of the singular-point search is empty or not finite", "box");
  if (!(std::isfinite(s.min_box_size) && s.min_box_size >= 0.0))
    throw SettingError("min_box_size", "the smallest box of the singular-point search must be 0 or positive");
  if (!(std::isfinite(s.spacing) && s.spacing >= 0.0))
    throw SettingError("spacing", "the spacing of singular points must be 0 or positive");
  if (s.max_boxes == 0) throw SettingError("max_boxes", "the singular-point search needs a budget of boxes");
  if (s.max_starts == 0)
    throw SettingError("max_starts", "the singular-point search needs a budget of starts");
  if (!(s.tolerance > 0.0 && s.tolerance < 1.0))
    throw SettingError("tolerance", "the tolerance of singular points must lie in (0, 1)");
}

}  // namespace

SingularPoints find_singular_points(const Surface& surface, const Box& box,
                                    const SingularSearchSettings& settings) {
  check_settings(box, settings);
  SingularPoints result;
  result.min_box_size =
      settings.min_box_size > 0.0 ? settings.min_box_size : kDefaultBoxFraction * box.size().maxCoeff();
  result.spacing = settings.spacing > 0.0 ? settings.spacing : result.min_box_size;
  if (!surface.gradient_bound(box)) {
    result.status = SingularSearchStatus::NotSearched;
    result.reason =
        "the surface gives no interval bounds (a C++ callable or a composite), which the search needs";
    return result;
  }
  result.status = SingularSearchStatus::Complete;

  // Subdivision, level by level: each level's enclosures in parallel into their own slots.
  std::vector<Box> level{box};
  std::vector<Box> starts;
  std::vector<std::uint8_t> keep;
  while (!level.empty()) {
    if (result.boxes + level.size() > settings.max_boxes) {
      result.status = SingularSearchStatus::BudgetExhausted;
      result.reason =
          "the subdivision reached its budget of " + std::to_string(settings.max_boxes) + " boxes";
      starts.insert(starts.end(), level.begin(), level.end());  // their centres are refined all the same
      break;
    }
    keep.assign(level.size(), static_cast<std::uint8_t>(Verdict::Undecided));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, level.size(), 16), [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i)
        keep[i] = static_cast<std::uint8_t>(examine(surface, level[i]));
    });
    result.boxes += level.size();
    std::vector<Box> next;
    for (std::size_t i = 0; i < level.size(); ++i) {
      const auto verdict = static_cast<Verdict>(keep[i]);
      if (verdict == Verdict::Excluded) continue;
      if (verdict == Verdict::Unique || level[i].size().maxCoeff() <= result.min_box_size) {
        starts.push_back(level[i]);
      } else {
        const std::array<Box, 2> halves = split(level[i]);
        next.push_back(halves[0]);
        next.push_back(halves[1]);
      }
    }
    level = std::move(next);
  }

  // Thinned evenly when there are more starts than the budget.
  if (starts.size() > settings.max_starts) {
    std::vector<Box> thinned;
    thinned.reserve(settings.max_starts);
    for (std::size_t k = 0; k < settings.max_starts; ++k)
      thinned.push_back(starts[k * starts.size() / settings.max_starts]);
    if (result.status == SingularSearchStatus::Complete)
      result.reason = std::to_string(starts.size()) + " boxes were left, more than the budget of " +
                      std::to_string(settings.max_starts) + " Newton starts";
    result.status = SingularSearchStatus::BudgetExhausted;
    starts = std::move(thinned);
  }
  result.starts = starts.size();

  std::vector<std::optional<singular::Converged>> runs(starts.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, starts.size(), 4), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i)
      runs[i] = refine(surface, starts[i], box.size().maxCoeff(), settings.tolerance);
  });
  const double margin = 1e-9 * box.diagonal();
  std::vector<singular::Converged> found;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!runs[i] || !box.contains(runs[i]->point, margin)) continue;
    if (settings.inside && !settings.inside(runs[i]->point)) continue;
    found.push_back(*runs[i]);
    found.back().start = i;
  }
  result.converged = found.size();
  const std::vector<singular::Converged> kept = singular::merge_converged(std::move(found), result.spacing);
  std::vector<std::uint8_t> smooth(kept.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, kept.size(), 4), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i)
      smooth[i] = singular::smooth_sheet(surface, kept[i].point, result.spacing) ? 1 : 0;
  });
  singular::group_points(kept, std::vector<bool>(smooth.begin(), smooth.end()), result.spacing, &result);
  return result;
}

}  // namespace isopatch
