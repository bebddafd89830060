#pragma once
// The samples of a sparse grid as an OpenVDB tree stores them, without OpenVDB: leaf bricks of 8^3
// values, constant tiles of larger power-of-two sizes, and a background everywhere else. What the .vdb
// reader fills (vdb_reader.hpp) and the sparse B-spline is made from (sparse_bspline.hpp).

#include <isopatch/geometry.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <unordered_map>
#include <vector>

namespace isopatch::vdb {

/// Integer voxel (or brick, or tile) coordinates.
using Coord = std::array<std::int64_t, 3>;

struct CoordHash {
  std::size_t operator()(const Coord& c) const {
    std::uint64_t h = 1469598103934665603ULL;
    for (const std::int64_t v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ULL;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

/// Floor division of a coordinate by a power of two 2^shift (correct for negative values).
inline std::int64_t floor_shift(std::int64_t v, int shift) {
  return v >> shift;
}

inline constexpr int kBrickShift = 3;  ///< bricks of 8^3 voxels: OpenVDB's leaf nodes
inline constexpr std::int64_t kBrick = std::int64_t{1} << kBrickShift;
inline constexpr std::size_t kBrickVoxels = 512;

/// Offset of voxel (x, y, z) inside its brick, x slowest (as OpenVDB's leaves).
inline std::size_t brick_offset(const Coord& voxel) {
  return static_cast<std::size_t>(((voxel[0] & 7) << 6) | ((voxel[1] & 7) << 3) | (voxel[2] & 7));
}

/// What a grid holds outside its leaves: constant tiles, and the background everywhere else. The
/// samples there and, unchanged by the filter, the spline's coefficients (sparse_bspline.hpp).
struct TileValues {
  double background = 0.0;
  /// Tiles other than the background by size shift (log2 of the side) and tile coordinate (voxel >> shift).
  std::map<int, std::unordered_map<Coord, double, CoordHash>> levels;

  /// The value of voxel `v` outside every leaf: its tile's, else the background.
  double value(const Coord& v) const {
    for (const auto& [shift, level] : levels) {
      const auto t =
          level.find({floor_shift(v[0], shift), floor_shift(v[1], shift), floor_shift(v[2], shift)});
      if (t != level.end()) return t->second;
    }
    return background;
  }
  /// Calls f(value) with the background and every tile's value.
  void for_each_value(const std::function<void(double)>& f) const {
    f(background);
    for (const auto& [shift, level] : levels)
      for (const auto& [key, v] : level) f(v);
  }
};

/// A grid's samples by voxel index, and how index space maps to space: voxel (i, j, k) sits at
/// origin + (i, j, k) * spacing.
struct SparseSamples {
  Vec3 spacing = Vec3::Ones();
  Vec3 origin = Vec3::Zero();
  /// Leaf bricks by brick coordinate (voxel >> 3), 512 values each.
  std::unordered_map<Coord, std::vector<double>, CoordHash> leaves;
  TileValues tiles;
  /// The smallest and largest index of an active voxel (valid when active_voxels > 0).
  Coord active_lo{0, 0, 0}, active_hi{0, 0, 0};
  std::uint64_t active_voxels = 0;
};

}  // namespace isopatch::vdb
