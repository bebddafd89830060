#pragma once
// A spatially coherent order of points: the Z-order (Morton) curve over their bounding box, so that
// points near each other in space are mostly near each other in the order. The clean-up renumbers its
// vertices in this order: a split appends its vertex at the end of the arrays, and after a round of
// splits of a large mesh, every pass over the vertices would otherwise jump across memory.
// The self-intersection check builds its tree of triangles along the same curve, and blocks cut a base
// along it. (Morton, "A computer oriented geodetic data base", IBM 1966; the standard use for mesh
// locality.)

#include <isopatch/geometry.hpp>

#include <cstdint>
#include <vector>

namespace isopatch {

/// The indices i with keep[i] (or every index when keep is empty), ordered along the Z-order curve of
/// points[i] quantised to 2^21 steps per axis of their bounding box; ties in the order of the index.
/// Deterministic. \pre keep is empty or has points.size() entries; points are finite.
std::vector<std::uint32_t> z_order(const std::vector<Vec3>& points, const std::vector<bool>& keep);

/// The 63-bit Z-order key of cell (x, y, z), each coordinate below 2^21 (bits interleaved, x lowest).
std::uint64_t z_order_key(std::uint32_t x, std::uint32_t y, std::uint32_t z);

/// The Z-order keys of points in a cube: its lower corner `lo` and side `extent` cut into 2^21 steps
/// per axis (points outside are clamped to it; a cube of side 0 gives every point key 0).
class ZOrderCube {
 public:
  ZOrderCube(const Vec3& lo, double extent);
  /// The key of p's step cell. \pre p is finite.
  std::uint64_t key(const Vec3& p) const;

 private:
  Vec3 lo_;
  double scale_;
};

}  // namespace isopatch
