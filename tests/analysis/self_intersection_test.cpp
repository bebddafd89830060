// find_self_intersections: hand-made pairs for each way two triangles can share vertices, and agreement
// with CGAL's Polygon Mesh Processing (an independent implementation with exact predicates) on meshes
// with folds and interpenetrating components.
#include <isopatch/error.hpp>
#include <isopatch/self_intersection.hpp>

#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include "analysis_meshes.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

/// A mesh of two triangles given by their corners (each triangle gets its own three vertices unless
/// `shared` corners of the second repeat those of the first: index i < 3 means the first's corner i).
Mesh pair(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b,
          std::array<int, 3> b_index = {3, 4, 5}) {
  Mesh m;
  for (const Vec3& p : a) m.positions.push_back(p);
  for (const Vec3& p : b) m.positions.push_back(p);
  m.triangles.push_back({0, 1, 2});
  m.triangles.push_back({static_cast<std::uint32_t>(b_index[0]), static_cast<std::uint32_t>(b_index[1]),
                         static_cast<std::uint32_t>(b_index[2])});
  return m;
}

std::size_t count(const Mesh& m) {
  return find_self_intersections(m).pairs;
}

const std::array<Vec3, 3> kFloor = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};

TEST(SelfIntersection, TrianglesWithoutACommonVertex) {
  // Crossing: a vertical triangle through the floor triangle.
  EXPECT_EQ(count(pair(kFloor, {Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 1), Vec3(1, 0.2, 0.5)})), 1u);
  // Above it, and beside it.
  EXPECT_EQ(count(pair(kFloor, {Vec3(0, 0, 0.1), Vec3(2, 0, 0.1), Vec3(0, 2, 0.1)})), 0u);
  EXPECT_EQ(count(pair(kFloor, {Vec3(3, 3, -1), Vec3(3, 3, 1), Vec3(4, 3, 0)})), 0u);
  // Touching: a vertex of the second on the floor's interior.
  EXPECT_EQ(count(pair(kFloor, {Vec3(0.5, 0.5, 0), Vec3(0.5, 0.5, 1), Vec3(1, 0.5, 1)})), 1u);
  // In one plane: overlapping, one inside the other, and apart.
  EXPECT_EQ(count(pair(kFloor, {Vec3(1, 1, 0), Vec3(3, 1, 0), Vec3(1, 3, 0)})), 1u);
  EXPECT_EQ(count(pair(kFloor, {Vec3(0.2, 0.2, 0), Vec3(0.5, 0.2, 0), Vec3(0.2, 0.5, 0)})), 1u);
  EXPECT_EQ(count(pair(kFloor, {Vec3(1.5, 1.5, 0), Vec3(3, 1.5, 0), Vec3(1.5, 3, 0)})), 0u);
}

TEST(SelfIntersection, TrianglesWithCommonVerticesMeetOnlyWhereTheyShouldNot) {
  // One common vertex (the floor's corner 0): apart, and with the second's far edge through the floor.
  EXPECT_EQ(count(pair(kFloor, {Vec3(0, 0, 0), Vec3(-1, 0, 1), Vec3(0, -1, 1)}, {0, 4, 5})), 0u);
  EXPECT_EQ(count(pair(kFloor, {Vec3(0, 0, 0), Vec3(1, 0.5, 1), Vec3(0.5, 1, -1)}, {0, 4, 5})), 1u);
  // One common vertex in one plane: overlapping sectors, and sectors apart.
  EXPECT_EQ(count(pair(kFloor, {Vec3(0, 0, 0), Vec3(1, 0.2, 0), Vec3(3, 3, 0)}, {0, 4, 5})), 1u);
  EXPECT_EQ(count(pair(kFloor, {Vec3(0, 0, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0)}, {0, 4, 5})), 0u);
  // A common edge (corners 0 and 1): a bent pair, an unfolded flat pair, a pair folded flat.
  EXPECT_EQ(count(pair(kFloor, {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, -1, 1)}, {1, 0, 5})), 0u);
  EXPECT_EQ(count(pair(kFloor, {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, -1, 0)}, {1, 0, 5})), 0u);
  EXPECT_EQ(count(pair(kFloor, {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0)}, {1, 0, 5})), 1u);
  // The same triangle twice.
  EXPECT_EQ(count(pair(kFloor, kFloor, {2, 1, 0})), 1u);
}

TEST(SelfIntersection, CleanClosedMeshesHaveNone) {
  EXPECT_EQ(count(test::icosphere(3)), 0u);
  EXPECT_EQ(count(test::parametric_torus(40, 20)), 0u);
  EXPECT_EQ(count(test::hexagon_fan()), 0u);  // flat: every pair in one plane
  EXPECT_EQ(count(Mesh{}), 0u);
}

TEST(SelfIntersection, NearlyCoplanarNeighboursAreDecidedExactly) {
  const Mesh flat = test::tilted_grid(40);
  EXPECT_EQ(count(flat), 0u);
  EXPECT_EQ(test::count_self_intersections(flat, 100000), 0u);
  // Folding one vertex's fan flat over its neighbour: a genuine overlap in the plane.
  Mesh folded = flat;
  const std::size_t v = 20 * 40 + 20;
  folded.positions[v] = folded.positions[v + 2];
  EXPECT_GT(count(folded), 0u);
  EXPECT_EQ(count(folded), test::count_self_intersections(folded, 100000));
}

/// Two icospheres of `subdivisions` (radii 1 and 0.8, the second moved by (0.9, 0.1, 0.05)) in one
/// mesh: their triangles cross along a circle.
Mesh spheres_through_each_other(int subdivisions) {
  Mesh two = test::icosphere(subdivisions);
  const Mesh second = test::icosphere(subdivisions, 0.8);
  const auto offset = static_cast<std::uint32_t>(two.positions.size());
  for (const Vec3& p : second.positions) two.positions.push_back(p + Vec3(0.9, 0.1, 0.05));
  for (const Triangle& t : second.triangles)
    two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return two;
}

TEST(SelfIntersection, AgreesWithCgalOnFoldsAndInterpenetration) {
  std::size_t folds = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(seed);
    const Mesh folded = test::jittered(test::icosphere(3), 12, 0.3, seed);
    const std::size_t expected = test::count_self_intersections(folded, 100000);
    EXPECT_EQ(count(folded), expected);
    folds += expected;
  }
  EXPECT_GT(folds, 10u);  // the jitter folds some of the spheres
  // A finer sphere folded in many places: a deep tree, whose seams between subtrees are scanned apart.
  const Mesh fine = test::jittered(test::icosphere(5), 300, 0.08, 7);
  const std::size_t fine_expected = test::count_self_intersections(fine, 100000);
  EXPECT_GT(fine_expected, 20u);
  EXPECT_EQ(count(fine), fine_expected);
  // Two spheres through each other: their triangles cross along a circle.
  const Mesh two = spheres_through_each_other(3);
  const SelfIntersectionReport r = find_self_intersections(two);
  EXPECT_GT(r.pairs, 20u);
  EXPECT_EQ(r.pairs, test::count_self_intersections(two, 100000));
  EXPECT_FALSE(r.capped);
  // The example point lies where the spheres meet: on both.
  EXPECT_NEAR(r.example_point.norm(), 1.0, 0.02);
  EXPECT_NEAR((r.example_point - Vec3(0.9, 0.1, 0.05)).norm(), 0.8, 0.02);
  const SelfIntersectionReport capped = find_self_intersections(two, 5);
  EXPECT_EQ(capped.pairs, 5u);
  EXPECT_TRUE(capped.capped);
}

TEST(SelfIntersection, TheReportIsTheSameForAnyNumberOfThreads) {
  // Large enough for many pieces of the parallel scan: two interpenetrating spheres of 20480
  // triangles each, the first pair and the count capped or not.
  const Mesh two = spheres_through_each_other(5);
  for (const std::size_t limit : {std::size_t{1}, std::size_t{7}, std::size_t{100000}}) {
    SCOPED_TRACE(limit);
    SelfIntersectionReport one, many;
    tbb::task_arena(1).execute([&] { one = find_self_intersections(two, limit); });
    tbb::task_arena(4).execute([&] { many = find_self_intersections(two, limit); });
    EXPECT_EQ(one.pairs, many.pairs);
    EXPECT_EQ(one.capped, many.capped);
    EXPECT_EQ(one.example, many.example);
    EXPECT_EQ(one.example_point, many.example_point);
    EXPECT_EQ(one.capped, limit < 1000);
    if (limit < 1000) {
      EXPECT_EQ(one.pairs, limit);
    }
  }
}

TEST(SelfIntersection, RejectsBadIndicesAndPositions) {
  Mesh m = test::icosphere(1);
  m.triangles.push_back({0, 1, static_cast<std::uint32_t>(m.positions.size())});
  EXPECT_THROW(find_self_intersections(m), InputError);
  Mesh n = test::icosphere(1);
  n.positions[3].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(find_self_intersections(n), InputError);
}

}  // namespace
}  // namespace isopatch
