// flat_fans (src/analysis/flat_fans.hpp), the proof that lets the self-intersection check skip the
// pairs of triangles around a vertex: it holds for the interior vertices of flat and smooth meshes, and
// never for a fan whose triangles meet elsewhere than in shared vertices and edges (checked with CGAL on
// every proved fan of folded spheres, and on fans made to overlap).
#include <isopatch/self_intersection.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "analysis/flat_fans.hpp"
#include "analysis_meshes.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

/// Vertex 0 with `n` neighbours at angles step * k (degrees) and radii `radius(k)`, heights `height(k)`,
/// in one closed fan.
template <class Radius, class Height>
Mesh fan(int n, double step, Radius radius, Height height) {
  Mesh m;
  m.positions.emplace_back(0, 0, 0);
  for (int k = 0; k < n; ++k) {
    const double a = step * k * std::numbers::pi / 180.0;
    m.positions.emplace_back(radius(k) * std::cos(a), radius(k) * std::sin(a), height(k));
  }
  for (int k = 0; k < n; ++k)
    m.triangles.push_back(
        {0, static_cast<std::uint32_t>(1 + k), static_cast<std::uint32_t>(1 + (k + 1) % n)});
  return m;
}

/// The triangles of `m` around vertex v as a mesh of their own.
Mesh fan_of(const Mesh& m, std::uint32_t v) {
  Mesh out;
  out.positions = m.positions;
  for (const Triangle& t : m.triangles)
    if (t[0] == v || t[1] == v || t[2] == v) out.triangles.push_back(t);
  return out;
}

TEST(FlatFans, InteriorVerticesOfAGridAreProvedAndItsBoundaryIsNot) {
  const int n = 12;
  const std::vector<std::uint8_t> proved = analysis::flat_fans(test::tilted_grid(n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const bool interior = i > 0 && j > 0 && i + 1 < n && j + 1 < n;
      EXPECT_EQ(proved[static_cast<std::size_t>(j * n + i)], interior ? 1 : 0) << i << ", " << j;
    }
}

TEST(FlatFans, ASmoothClosedMeshIsProvedEverywhere) {
  const Mesh sphere = test::icosphere(4);
  const std::vector<std::uint8_t> proved = analysis::flat_fans(sphere);
  for (std::size_t v = 0; v < proved.size(); ++v) EXPECT_EQ(proved[v], 1) << v;
}

TEST(FlatFans, AFanThatWindsTwiceIsNotProvedAndItsOverlapsAreFound) {
  // Six neighbours at 120 degree steps in one plane: two turns, the second on a wider circle. The
  // projection along z keeps every triangle's orientation but winds twice; along x and y it is flat.
  const Mesh twice = fan(
      6, 120.0, [](int k) { return k < 3 ? 1.0 : 2.0; }, [](int) { return 0.0; });
  EXPECT_EQ(analysis::flat_fans(twice)[0], 0);
  const std::size_t overlaps = test::count_self_intersections(twice, 1000);
  EXPECT_GT(overlaps, 0u);
  EXPECT_EQ(find_self_intersections(twice).pairs, overlaps);
  // The same lifted into a screw (heights rising by turn) does not meet itself, and is not proved
  // either: it is tested pair by pair.
  const Mesh screw = fan(
      6, 120.0, [](int) { return 1.0; }, [](int k) { return 0.4 * k; });
  EXPECT_EQ(analysis::flat_fans(screw)[0], 0);
  EXPECT_EQ(find_self_intersections(screw).pairs, test::count_self_intersections(screw, 1000));
}

TEST(FlatFans, AFoldedFanIsNotProved) {
  // A hexagon with one neighbour pulled across the centre: two triangles turn over in every projection.
  Mesh folded = fan(
      6, 60.0, [](int) { return 1.0; }, [](int) { return 0.0; });
  EXPECT_EQ(analysis::flat_fans(folded)[0], 1);
  folded.positions[1] = Vec3(-0.5, 0.05, 0.0);
  EXPECT_EQ(analysis::flat_fans(folded)[0], 0);
  EXPECT_EQ(find_self_intersections(folded).pairs, test::count_self_intersections(folded, 1000));
  EXPECT_GT(find_self_intersections(folded).pairs, 0u);
}

TEST(FlatFans, EveryProvedFanOfFoldedSpheresMeetsOnlyWhereItShares) {
  std::size_t unproved = 0, proved_count = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const Mesh m = test::jittered(test::icosphere(3), 40, 0.3, seed);
    const std::vector<std::uint8_t> proved = analysis::flat_fans(m);
    for (std::uint32_t v = 0; v < proved.size(); ++v) {
      if (proved[v] == 0) {
        ++unproved;
        continue;
      }
      ++proved_count;
      ASSERT_EQ(test::count_self_intersections(fan_of(m, v), 10), 0u) << "seed " << seed << ", vertex " << v;
    }
  }
  EXPECT_GT(unproved, 10u);  // the jitter folds some fans
  EXPECT_GT(proved_count, 1000u);
}

}  // namespace
}  // namespace isopatch
