#pragma once
/// \file point_index.hpp
/// The vertices of a partition of convex cells, numbered once: a point within the tolerance of one
/// already known gets that point's id (cells compute their shared corners independently, and a plane
/// clip rounds), found through a hash grid. Ids follow the order of first insertion, so a partition
/// built in a fixed order numbers its vertices the same way every time.

#include <isopatch/geometry.hpp>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace isopatch {

class PointIndex {
 public:
  /// \param spacing    the hash grid's step (about a cell's size), > 0
  /// \param tolerance  points this close are one point, > 0 and well below `spacing`
  PointIndex(const Vec3& origin, double spacing, double tolerance);

  /// The id of p: the first known point within the tolerance, else a new id.
  std::uint32_t insert(const Vec3& p);
  /// The known points within `radius` (<= spacing) of the segment from a to b, ascending by id.
  std::vector<std::uint32_t> near_segment(const Vec3& a, const Vec3& b, double radius) const;

  const std::vector<Vec3>& points() const { return points_; }
  double tolerance() const { return tolerance_; }

 private:
  using Key = std::uint64_t;
  Key key(std::int64_t i, std::int64_t j, std::int64_t k) const;
  std::array<std::int64_t, 3> cell_of(const Vec3& p) const;

  Vec3 origin_;
  double spacing_;
  double tolerance_;
  std::vector<Vec3> points_;
  std::unordered_map<Key, std::vector<std::uint32_t>> grid_;
};

}  // namespace isopatch
