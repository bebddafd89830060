// The Z-order of points, see spatial_order.hpp.
#include "core/spatial_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace isopatch {
namespace {

constexpr double kSteps = 2097151.0;  // 2^21 - 1

/// The 21 low bits of v spread to every third bit.
std::uint64_t spread_bits(std::uint32_t v) {
  std::uint64_t x = v & 0x1fffffu;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

}  // namespace

std::uint64_t z_order_key(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  return spread_bits(x) | spread_bits(y) << 1 | spread_bits(z) << 2;
}

ZOrderCube::ZOrderCube(const Vec3& lo, double extent)
    : lo_(lo), scale_(extent > 0.0 ? kSteps / extent : 0.0) {}

std::uint64_t ZOrderCube::key(const Vec3& p) const {
  std::uint32_t cell[3];
  for (int c = 0; c < 3; ++c)
    cell[c] = static_cast<std::uint32_t>(std::clamp((p[c] - lo_[c]) * scale_, 0.0, kSteps));
  return z_order_key(cell[0], cell[1], cell[2]);
}

std::vector<std::uint32_t> z_order(const std::vector<Vec3>& points, const std::vector<bool>& keep) {
  const auto kept = [&](std::size_t i) { return keep.empty() || keep[i]; };
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()),
       hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < points.size(); ++i)
    if (kept(i)) lo = lo.cwiseMin(points[i]), hi = hi.cwiseMax(points[i]);
  const ZOrderCube cube(lo, (hi - lo).maxCoeff());
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  keyed.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!kept(i)) continue;
    keyed.emplace_back(cube.key(points[i]), static_cast<std::uint32_t>(i));
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order;
  order.reserve(keyed.size());
  for (const auto& [key, i] : keyed) order.push_back(i);
  return order;
}

}  // namespace isopatch
