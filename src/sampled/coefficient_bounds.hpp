#pragma once
// Exact smallest and largest values over boxes of a grid of B-spline coefficients, and of the grid's
// differences of neighbours along each axis, answered from per-brick summaries: the convex-hull bounds
// of a sampled volume (volume_surface.hpp) in time proportional to the bricks a box covers instead of
// its coefficients. The answers are the very minimum and maximum of the same values a scan of the box
// finds (no rounding is involved), so bounds made from them are the scan's to the bit.

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace isopatch::bspline {

/// Indices lo..hi, both included.
struct IndexRange {
  std::size_t lo = 0, hi = 0;
};
using IndexBox = std::array<IndexRange, 3>;

class CoefficientBounds {
 public:
  /// Summarises the grid of `shape` (each side >= 2) at `c` (C order; must outlive this object) in
  /// bricks of kBrick^3 coefficients. O(coefficients) time, one pass; memory 1/32 of the grid's.
  CoefficientBounds(const double* c, const std::array<std::size_t, 3>& shape);

  /// Smallest and largest c over `box` (inside the grid).
  std::pair<double, double> values(const IndexBox& box) const;
  /// Smallest and largest c[p + e_axis] - c[p] over p in `box` (inside the grid, and box[axis].hi at
  /// most shape[axis] - 2).
  std::pair<double, double> differences(int axis, const IndexBox& box) const;

  static constexpr std::size_t kBrick = 8;

 private:
  struct Summary {
    double lo, hi;
  };
  /// query 0: values; 1 + axis: differences along that axis.
  std::pair<double, double> query(int kind, const IndexBox& box) const;
  std::pair<double, double> scan(int kind, const IndexBox& box) const;
  /// The offset from a coefficient to the neighbour its difference of `kind` subtracts (0: values).
  std::size_t step(int kind) const;

  const double* c_;
  std::array<std::size_t, 3> shape_, bricks_;
  /// Per brick (C order over bricks_) and kind: the range of its values.
  std::array<std::vector<Summary>, 4> summary_;
};

}  // namespace isopatch::bspline
