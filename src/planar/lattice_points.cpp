// Interior points of a planar region on the triangular lattice (lattice_points.hpp).
#include "planar/lattice_points.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>

namespace isopatch::planar {

namespace {

/// The segments near a point: a hash grid of cells `size` across holding the segments whose bounds,
/// grown by `size`, touch the cell.
class SegmentGrid {
 public:
  SegmentGrid(const Region& region, double size) : region_(region), size_(size) {
    for (std::size_t s = 0; s < region.segments.size(); ++s) {
      const Vec2& a = region.points[region.segments[s][0]];
      const Vec2& b = region.points[region.segments[s][1]];
      const Cell lo = cell_of(a.cwiseMin(b) - Vec2::Constant(size));
      const Cell hi = cell_of(a.cwiseMax(b) + Vec2::Constant(size));
      for (std::int64_t y = lo.second; y <= hi.second; ++y)
        for (std::int64_t x = lo.first; x <= hi.first; ++x) cells_[key(x, y)].push_back(s);
    }
  }

  /// The distance from p to the nearest segment, or `size` when none is within it.
  double distance(const Vec2& p) const {
    const Cell c = cell_of(p);
    const auto it = cells_.find(key(c.first, c.second));
    double best = size_;
    if (it == cells_.end()) return best;
    for (std::size_t s : it->second) {
      const Vec2& a = region_.points[region_.segments[s][0]];
      const Vec2& b = region_.points[region_.segments[s][1]];
      const Vec2 d = b - a;
      const double l2 = d.squaredNorm();
      const double t = l2 > 0.0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
      best = std::min(best, (a + t * d - p).norm());
    }
    return best;
  }

 private:
  using Cell = std::pair<std::int64_t, std::int64_t>;
  const Region& region_;
  double size_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;

  Cell cell_of(const Vec2& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / size_)),
            static_cast<std::int64_t>(std::floor(p.y() / size_))};
  }
  static std::uint64_t key(std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(x) << 32) ^ (static_cast<std::uint64_t>(y) & 0xffffffffULL);
  }
};

/// One crossing of a lattice row by a segment: its x and +1 upwards, -1 downwards.
struct Crossing {
  double x;
  int sign;
};

}  // namespace

std::vector<Vec2> interior_lattice_points(const Region& region, double spacing, double clearance) {
  std::vector<Vec2> out;
  if (region.segments.empty() || !(spacing > 0.0)) return out;
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 hi = -lo;
  for (const auto& s : region.segments)
    for (std::uint32_t i : s) {
      lo = lo.cwiseMin(region.points[i]);
      hi = hi.cwiseMax(region.points[i]);
    }
  const double row = spacing * std::sqrt(3.0) / 2.0;
  const auto rows = static_cast<std::size_t>(std::floor((hi.y() - lo.y()) / row)) + 1;
  // Each segment crosses the rows whose y lies in [low end, high end) (half-open, so a row through a
  // point is crossed once by the two segments at it).
  std::vector<std::vector<Crossing>> crossings(rows);
  for (const auto& s : region.segments) {
    const Vec2& a = region.points[s[0]];
    const Vec2& b = region.points[s[1]];
    if (a.y() == b.y()) continue;
    const Vec2& low = a.y() < b.y() ? a : b;
    const Vec2& high = a.y() < b.y() ? b : a;
    const int sign = a.y() < b.y() ? 1 : -1;
    const auto first = static_cast<std::int64_t>(std::ceil((low.y() - lo.y()) / row));
    for (auto j = std::max<std::int64_t>(first, 0); j < static_cast<std::int64_t>(rows); ++j) {
      const double y = lo.y() + static_cast<double>(j) * row;
      if (y >= high.y()) break;
      if (y < low.y()) continue;
      const double x = low.x() + (y - low.y()) * (high.x() - low.x()) / (high.y() - low.y());
      crossings[static_cast<std::size_t>(j)].push_back({x, sign});
    }
  }
  const SegmentGrid near(region, std::max(clearance, spacing));
  for (std::size_t j = 0; j < rows; ++j) {
    std::vector<Crossing>& c = crossings[j];
    std::sort(c.begin(), c.end(), [](const Crossing& p, const Crossing& q) { return p.x < q.x; });
    const double y = lo.y() + static_cast<double>(j) * row;
    const double shift = (j % 2 == 1) ? 0.5 * spacing : 0.0;
    // The winding number of a point: the signs of the crossings to its right (a counter-clockwise
    // loop's right side goes up).
    int right = 0;
    for (const Crossing& k : c) right += k.sign;
    std::size_t next = 0;
    const auto columns = static_cast<std::size_t>(std::floor((hi.x() - lo.x() - shift) / spacing)) + 1;
    for (std::size_t i = 0; i < columns; ++i) {
      const double x = lo.x() + shift + static_cast<double>(i) * spacing;
      while (next < c.size() && c[next].x <= x) right -= c[next++].sign;
      if (right <= 0) continue;
      const Vec2 p(x, y);
      if (near.distance(p) >= clearance) out.push_back(p);
    }
  }
  return out;
}

}  // namespace isopatch::planar
