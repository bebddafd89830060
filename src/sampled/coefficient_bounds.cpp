// Brick summaries of a coefficient grid for exact range queries (coefficient_bounds.hpp).
#include "sampled/coefficient_bounds.hpp"

#include <algorithm>
#include <limits>

namespace isopatch::bspline {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

std::size_t CoefficientBounds::step(int kind) const {
  return kind == 1 ? shape_[1] * shape_[2] : kind == 2 ? shape_[2] : kind == 3 ? 1 : 0;
}

CoefficientBounds::CoefficientBounds(const double* c, const std::array<std::size_t, 3>& shape)
    : c_(c), shape_(shape) {
  for (std::size_t a = 0; a < 3; ++a) bricks_[a] = (shape_[a] + kBrick - 1) / kBrick;
  const std::size_t count = bricks_[0] * bricks_[1] * bricks_[2];
  for (auto& s : summary_) s.assign(count, Summary{kInf, -kInf});
  // One pass over the grid: every coefficient, and every difference that starts at it, into its brick.
  for (std::size_t i = 0; i < shape_[0]; ++i)
    for (std::size_t j = 0; j < shape_[1]; ++j) {
      const std::size_t row = ((i / kBrick) * bricks_[1] + j / kBrick) * bricks_[2];
      for (std::size_t k = 0; k < shape_[2]; ++k) {
        const std::size_t b = row + k / kBrick;
        const std::array<std::size_t, 3> p{i, j, k};
        for (int kind = 0; kind < 4; ++kind) {
          if (kind > 0 &&
              p[static_cast<std::size_t>(kind - 1)] + 1 >= shape_[static_cast<std::size_t>(kind - 1)])
            continue;  // no neighbour after it along that axis
          const double* at = c_ + (i * shape_[1] + j) * shape_[2] + k;
          const double v = kind == 0 ? *at : at[step(kind)] - *at;
          Summary& s = summary_[static_cast<std::size_t>(kind)][b];
          s.lo = std::min(s.lo, v);
          s.hi = std::max(s.hi, v);
        }
      }
    }
}

std::pair<double, double> CoefficientBounds::scan(int kind, const IndexBox& box) const {
  const std::size_t n1 = shape_[1], n2 = shape_[2];
  const std::size_t next = step(kind);
  double lo = kInf, hi = -kInf;
  for (std::size_t i = box[0].lo; i <= box[0].hi; ++i)
    for (std::size_t j = box[1].lo; j <= box[1].hi; ++j) {
      const double* row = c_ + (i * n1 + j) * n2;
      for (std::size_t k = box[2].lo; k <= box[2].hi; ++k) {
        const double v = next == 0 ? row[k] : row[k + next] - row[k];
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
  return {lo, hi};
}

std::pair<double, double> CoefficientBounds::query(int kind, const IndexBox& box) const {
  double lo = kInf, hi = -kInf;
  // The last index a brick can hold along each axis (one less along a difference's axis).
  std::array<std::size_t, 3> last{shape_[0] - 1, shape_[1] - 1, shape_[2] - 1};
  if (kind > 0) --last[static_cast<std::size_t>(kind - 1)];
  std::array<std::size_t, 3> b{};
  for (b[0] = box[0].lo / kBrick; b[0] <= box[0].hi / kBrick; ++b[0])
    for (b[1] = box[1].lo / kBrick; b[1] <= box[1].hi / kBrick; ++b[1])
      for (b[2] = box[2].lo / kBrick; b[2] <= box[2].hi / kBrick; ++b[2]) {
        IndexBox part;
        bool whole = true;
        for (std::size_t a = 0; a < 3; ++a) {
          const std::size_t first = b[a] * kBrick, end = std::min(first + kBrick - 1, last[a]);
          part[a] = {std::max(first, box[a].lo), std::min(end, box[a].hi)};
          whole = whole && part[a].lo == first && part[a].hi == end;
        }
        std::pair<double, double> r;
        if (whole) {
          const Summary& s =
              summary_[static_cast<std::size_t>(kind)][(b[0] * bricks_[1] + b[1]) * bricks_[2] + b[2]];
          r = {s.lo, s.hi};
        } else {
          r = scan(kind, part);
        }
        lo = std::min(lo, r.first);
        hi = std::max(hi, r.second);
      }
  return {lo, hi};
}

std::pair<double, double> CoefficientBounds::values(const IndexBox& box) const {
  return query(0, box);
}

std::pair<double, double> CoefficientBounds::differences(int axis, const IndexBox& box) const {
  return query(1 + axis, box);
}

}  // namespace isopatch::bspline
