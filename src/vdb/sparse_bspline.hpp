#pragma once
// A tricubic B-spline over a sparse grid (vdb_surface.hpp): coefficients by the cubic quasi-interpolant
// c = P_x P_y P_z v, P = (-1, 8, -1) / 6 along each axis, stored in bricks of 8^3 for every leaf of the
// samples and every brick position next to one; elsewhere a coefficient is the tile's (or background's)
// value, which the filter leaves as it is where all neighbours share it. Evaluation, and convex-hull
// bounds from per-brick summaries and the tiles' values by side of the level.

#include <isopatch/derivatives.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include "sampled/bspline.hpp"
#include "vdb/sparse_samples.hpp"

namespace isopatch::vdb {

class SparseBspline {
 public:
  /// The coefficients of `samples` (see the file comment); `level` splits the tiles' values into the
  /// sides the bounds use. Takes the tiles over (`samples` keeps its leaves). O(bricks) time and memory.
  SparseBspline(SparseSamples&& samples, double level);

  /// The spline and its derivatives (Order 0, 1, 2) at index coordinates `u` (voxel (i, j, k) at
  /// u = (i, j, k)), with respect to u. \pre every |u| < 2^60.
  template <int Order>
  SecondOrder evaluate(const std::array<double, 3>& u) const {
    std::array<bspline::Weights, 3> w;
    std::array<std::int64_t, 3> first{};  // the first of the four coefficient indices along each axis
    std::array<std::int64_t, 3> low_brick{};
    for (std::size_t a = 0; a < 3; ++a) {
      const double cell = std::floor(u[a]);
      w[a] = bspline::weights(u[a] - cell);
      first[a] = static_cast<std::int64_t>(cell) - 1;
      low_brick[a] = floor_shift(first[a], kBrickShift);
    }
    // The four indices along an axis reach at most two bricks: the coefficients of the (up to) eight.
    std::array<const float*, 8> brick{};
    std::array<double, 8> constant{};
    for (std::size_t n = 0; n < 8; ++n) {
      const Coord key{low_brick[0] + static_cast<std::int64_t>(n >> 2),
                      low_brick[1] + static_cast<std::int64_t>((n >> 1) & 1),
                      low_brick[2] + static_cast<std::int64_t>(n & 1)};
      brick[n] = find(key);
      if (!brick[n]) constant[n] = tiles_.value({key[0] * kBrick, key[1] * kBrick, key[2] * kBrick});
    }
    return bspline::tricubic<Order>(w, [&](std::size_t a, std::size_t b, std::size_t c) {
      const Coord v{first[0] + static_cast<std::int64_t>(a), first[1] + static_cast<std::int64_t>(b),
                    first[2] + static_cast<std::int64_t>(c)};
      const std::size_t n = static_cast<std::size_t>(((floor_shift(v[0], kBrickShift) - low_brick[0]) << 2) |
                                                     ((floor_shift(v[1], kBrickShift) - low_brick[1]) << 1) |
                                                     (floor_shift(v[2], kBrickShift) - low_brick[2]));
      return brick[n] ? static_cast<double>(brick[n][brick_offset(v)]) : constant[n];
    });
  }

  /// Smallest and largest coefficient over the index box [lo, hi] (both included) and, when `gradient`,
  /// the smallest and largest difference c[p + e_a] - c[p] of neighbours in it along each axis a: sound
  /// enclosures (they may be wider).
  struct Hull {
    double lo = 0.0, hi = 0.0;
    std::array<double, 3> dlo{}, dhi{};
  };
  Hull hull(const Coord& lo, const Coord& hi, bool gradient) const;

  /// The coefficient of voxel `v`.
  double coefficient(const Coord& v) const;
  /// Bytes held: coefficients, brick index, summaries, tiles.
  std::size_t bytes() const;

 private:
  struct Summary {
    double lo, hi;
    std::array<double, 3> dlo, dhi;  // differences from each voxel to its next along each axis, and
                                     // from the voxel before the brick's low face to that face
  };
  /// Range of values (and of differences among them) of the tiles and background on one side.
  struct Side {
    bool present = false;
    double lo = 0.0, hi = 0.0;
  };

  const float* find(const Coord& brick) const {
    const auto it = index_.find(brick);
    return it == index_.end() ? nullptr : &coefficients_[static_cast<std::size_t>(it->second) * kBrickVoxels];
  }
  void summarise();
  /// The coefficients of the index box [lo, hi], x slowest.
  std::vector<double> gather(const Coord& lo, const Coord& hi) const;
  /// The hull of a small box from its coefficients themselves.
  Hull scan(const Coord& lo, const Coord& hi, bool gradient) const;
  void add_side(Hull& h, const Side& side, bool gradient) const;

  std::vector<Coord> keys_;  // brick coordinates, sorted
  std::unordered_map<Coord, std::uint32_t, CoordHash> index_;
  std::vector<float> coefficients_;  // kBrickVoxels per brick, in the order of keys_
  std::vector<Summary> summary_;
  TileValues tiles_;  // the coefficients outside every stored brick
  double level_ = 0.0;
  std::array<Side, 2> sides_;  // 0: below the level, 1: at or above it
};

}  // namespace isopatch::vdb
