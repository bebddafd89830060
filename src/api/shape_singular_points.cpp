// The singular points of a shape: of its smooth operands where they are the branch f takes (isopatch.hpp).
#include <isopatch/isopatch.hpp>
#include <isopatch/singular_points.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "csg/smooth_operands.hpp"

namespace isopatch {

namespace {

/// Operands searched one at a time at most; a formula with more is searched whole.
constexpr std::size_t kMostOperands = 64;

/// One component with its samples.
struct Found {
  SingularComponent component;
  std::vector<Vec3> samples;
};

/// Whether f takes the operand's branch at p: both read the same there (the operand is f with its
/// switches fixed, the same steps on the same values), to rounding.
bool operand_taken(const Surface& f, const Surface& operand, const Vec3& p) {
  const double a = f.value(p), b = operand.value(p);
  return std::isfinite(a) && std::isfinite(b) && std::abs(a - b) <= 1e-12 * (1.0 + std::abs(a) + std::abs(b));
}

/// How complete a status is (the smaller, the less).
int completeness(SingularSearchStatus s) {
  switch (s) {
    case SingularSearchStatus::NotSearched:
      return 0;
    case SingularSearchStatus::BudgetExhausted:
      return 1;
    case SingularSearchStatus::Complete:
      return 2;
  }
  return 0;
}

}  // namespace

SingularPoints find_shape_singular_points(const Surface& f, const Box& box,
                                          const SingularSearchSettings& settings) {
  const std::optional<std::vector<SurfacePtr>> operands = smooth_operands(f, box, kMostOperands);
  if (!operands) return find_singular_points(f, box, settings);
  SingularPoints out;
  out.status = SingularSearchStatus::Complete;
  std::vector<Found> found;
  for (const SurfacePtr& operand : *operands) {
    const SingularPoints one = find_singular_points(*operand, box, settings);
    if (completeness(one.status) < completeness(out.status)) {
      out.status = one.status;
      out.reason = one.reason;
    }
    out.min_box_size = one.min_box_size;
    out.spacing = one.spacing;
    out.boxes += one.boxes;
    out.starts += one.starts;
    out.converged += one.converged;
    std::size_t first = 0;
    for (const SingularComponent& c : one.components) {
      Found piece{c, {}};
      for (std::size_t k = first; k < first + c.samples; ++k)
        if (operand_taken(f, *operand, one.points[k])) piece.samples.push_back(one.points[k]);
      first += c.samples;
      if (piece.samples.empty()) continue;
      if (!operand_taken(f, *operand, c.position)) piece.component.position = piece.samples.front();
      piece.component.samples = piece.samples.size();
      piece.component.curve = piece.samples.size() >= 2;
      Box extent{piece.samples.front(), piece.samples.front()};
      for (const Vec3& p : piece.samples) {
        extent.lo = extent.lo.cwiseMin(p);
        extent.hi = extent.hi.cwiseMax(p);
      }
      piece.component.extent = extent;
      found.push_back(std::move(piece));
    }
  }
  // As find_singular_points orders them: the singular components first, then the smooth-sheet ones, each
  // group by position.
  std::stable_sort(found.begin(), found.end(), [](const Found& a, const Found& b) {
    const Vec3& p = a.component.position;
    const Vec3& q = b.component.position;
    return std::make_tuple(a.component.smooth_sheet, p.x(), p.y(), p.z()) <
           std::make_tuple(b.component.smooth_sheet, q.x(), q.y(), q.z());
  });
  // An operand that appears twice (a subexpression two switches share) gives its points twice.
  found.erase(std::unique(found.begin(), found.end(),
                          [](const Found& a, const Found& b) {
                            return a.component.smooth_sheet == b.component.smooth_sheet &&
                                   a.samples == b.samples;
                          }),
              found.end());
  for (Found& piece : found) {
    out.points.insert(out.points.end(), piece.samples.begin(), piece.samples.end());
    out.components.push_back(piece.component);
  }
  return out;
}

}  // namespace isopatch
