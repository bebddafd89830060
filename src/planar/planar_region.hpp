#pragma once
// A region of the plane bounded by directed segments (the region on their left), the shared vocabulary
// of planar_region's point placement (lattice_points.hpp) and triangulation
// (region_triangulation.hpp): the caps of a solid cut by planes (api/capped_meshing.hpp).

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace isopatch::planar {

using Vec2 = Eigen::Vector2d;

/// Closed loops of directed segments between `points`; the region lies on the left of every segment
/// (outer loops counter-clockwise, holes clockwise). Loops may share points but no segment crosses
/// another.
struct Region {
  std::vector<Vec2> points;
  std::vector<std::array<std::uint32_t, 2>> segments;
};

}  // namespace isopatch::planar
