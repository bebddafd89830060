// Vertex numbering by a hash grid (point_index.hpp).
#include "partition/point_index.hpp"

#include <algorithm>
#include <cmath>

namespace isopatch {

PointIndex::PointIndex(const Vec3& origin, double spacing, double tolerance)
    : origin_(origin), spacing_(spacing), tolerance_(tolerance) {}

PointIndex::Key PointIndex::key(std::int64_t i, std::int64_t j, std::int64_t k) const {
  // 21 bits per axis (offset to be non-negative): far more cells than a partition has per axis.
  constexpr std::int64_t kBias = std::int64_t{1} << 20;
  const auto u = [](std::int64_t v) { return static_cast<std::uint64_t>((v + kBias) & 0x1fffff); };
  return (u(i) << 42) | (u(j) << 21) | u(k);
}

std::array<std::int64_t, 3> PointIndex::cell_of(const Vec3& p) const {
  std::array<std::int64_t, 3> c{};
  for (int a = 0; a < 3; ++a)
    c[static_cast<std::size_t>(a)] = static_cast<std::int64_t>(std::floor((p[a] - origin_[a]) / spacing_));
  return c;
}

std::uint32_t PointIndex::insert(const Vec3& p) {
  const auto lo = cell_of(p - Vec3::Constant(tolerance_));
  const auto hi = cell_of(p + Vec3::Constant(tolerance_));
  std::uint32_t best = static_cast<std::uint32_t>(points_.size());
  for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
    for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
      for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
        if (const auto it = grid_.find(key(i, j, k)); it != grid_.end())
          for (std::uint32_t id : it->second)
            if (id < best && (points_[id] - p).norm() <= tolerance_) best = id;
  if (best < points_.size()) return best;
  points_.push_back(p);
  const auto c = cell_of(p);
  grid_[key(c[0], c[1], c[2])].push_back(best);
  return best;
}

std::vector<std::uint32_t> PointIndex::near_segment(const Vec3& a, const Vec3& b, double radius) const {
  const auto lo = cell_of(a.cwiseMin(b) - Vec3::Constant(radius));
  const auto hi = cell_of(a.cwiseMax(b) + Vec3::Constant(radius));
  const Vec3 d = b - a;
  const double length2 = d.squaredNorm();
  std::vector<std::uint32_t> found;
  for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
    for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
      for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
        if (const auto it = grid_.find(key(i, j, k)); it != grid_.end())
          for (std::uint32_t id : it->second) {
            const Vec3& p = points_[id];
            const double t = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
            if ((a + t * d - p).norm() <= radius) found.push_back(id);
          }
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace isopatch
