// Lattice geometry, keys, cell naming and the pure sample tests.
#include "partition/lattice.hpp"
#include "partition/cell.hpp"
#include "partition/cell_tests.hpp"

#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <vector>

namespace isopatch {
namespace {

TEST(Lattice, RootCubeCoversTheBoxAndIsShifted) {
  const Box box{Vec3(-1.0, -0.5, -0.25), Vec3(1.0, 0.5, 0.25)};
  const Lattice lattice = make_lattice(box, 6);
  EXPECT_DOUBLE_EQ(lattice.size, 2.04);
  const Box root{lattice.origin, lattice.origin + Vec3::Constant(lattice.size)};
  EXPECT_TRUE(root.contains(box.lo));
  EXPECT_TRUE(root.contains(box.hi));
  // Not centred: the non-dyadic offset moves the root off the symmetric position on every axis.
  for (int a = 0; a < 3; ++a) EXPECT_NE(root.centre()[a], box.centre()[a]);
  // Positions are clipped to the box: the root cell as the partition sees it is the box itself.
  const Box clipped = lattice.cell_box(0, {0, 0, 0});
  EXPECT_EQ(clipped.lo, box.lo);
  EXPECT_EQ(clipped.hi, box.hi);
  EXPECT_THROW(make_lattice(box, 21), InputError);
  EXPECT_THROW(make_lattice(Box{Vec3::Zero(), Vec3(1, 0, 1)}, 3), InputError);
}

TEST(Lattice, HalfAndFinestCoordinatesGiveIdenticalBits) {
  const Lattice lattice = make_lattice(Box{Vec3(-1.3, 0.1, 2.0), Vec3(0.7, 0.4, 2.9)}, 20);
  for (std::uint32_t i : {0u, 1u, 3u, 12345u, 777777u, 1u << 20}) {
    const LatticePoint p{i, (i * 7) % (1u << 20), (1u << 20) - i};
    const Vec3 a = lattice.point(p);
    const Vec3 b = lattice.half_point({2 * p[0], 2 * p[1], 2 * p[2]});
    EXPECT_EQ(a.x(), b.x());
    EXPECT_EQ(a.y(), b.y());
    EXPECT_EQ(a.z(), b.z());
  }
  const Box cell = lattice.cell_box(20, {1u << 19, 1u << 18, 1u << 19});
  EXPECT_NEAR(cell.size().x(), lattice.unit(), 1e-15);
}

TEST(Lattice, CellsAroundASegmentShareItsStartAsAnEdgePoint) {
  // A z segment at (4, 6, 2): the four cells around it have lower corners (4|3, 6|5, 2).
  const CellsAroundSegment inner = cells_around_segment(SegmentKey{{4, 6, 2}, 2, 1});
  ASSERT_EQ(inner.count, 4u);
  std::set<LatticePoint> got(inner.points.begin(), inner.points.end());
  EXPECT_EQ(got, (std::set<LatticePoint>{{4, 6, 2}, {3, 6, 2}, {4, 5, 2}, {3, 5, 2}}));
  // On the lattice boundary (x = 0) only the cells with non-negative coordinates remain.
  const CellsAroundSegment edge = cells_around_segment(SegmentKey{{0, 6, 2}, 2, 1});
  ASSERT_EQ(edge.count, 2u);
  EXPECT_EQ(edge.points[0], (LatticePoint{0, 6, 2}));
  EXPECT_EQ(edge.points[1], (LatticePoint{0, 5, 2}));
}

TEST(Lattice, NeverLeavesTheBoxAndFlattensCellsOutsideIt) {
  const Box box{Vec3(-1.0, -0.5, -0.25), Vec3(1.0, 0.5, 0.25)};
  const Lattice lattice = make_lattice(box, 4);
  int inside = 0, outside = 0;
  for (std::uint32_t i = 0; i < 16; ++i)
    for (std::uint32_t j = 0; j < 16; ++j)
      for (std::uint32_t k = 0; k < 16; ++k) {
        const Box cell = lattice.cell_box(4, {i, j, k});
        EXPECT_TRUE(box.contains(cell.lo) && box.contains(cell.hi));
        if (lattice.inside(4, {i, j, k})) {
          ++inside;
          EXPECT_TRUE((cell.lo.array() < cell.hi.array()).all());
        } else {
          ++outside;
          EXPECT_FALSE((cell.lo.array() < cell.hi.array()).all());
        }
      }
  // The box spans the whole root along x, about half of it along y and a quarter along z.
  EXPECT_GT(outside, 0);
  EXPECT_GT(inside, 16 * 8 * 4 - 1);
}

TEST(Lattice, HalfKeysAreInjectiveAtTheExtremes) {
  std::set<std::uint64_t> keys;
  const std::uint32_t top = 1u << 21;
  const std::array<std::uint32_t, 4> values{0, 1, top - 1, top};
  for (auto x : values)
    for (auto y : values)
      for (auto z : values) keys.insert(half_key({x, y, z}));
  EXPECT_EQ(keys.size(), 64u);
}

TEST(Cell, NeighboursNameSharedFacesAndEdgesAlike) {
  const Lattice lattice = make_lattice(Box{Vec3::Zero(), Vec3::Ones()}, 5);
  const Cell a = Cell::make(lattice, 3, {2, 3, 4});
  const Cell b = Cell::make(lattice, 3, {3, 3, 4});  // across a's x = 1 face (face 2) / b's x = 0 face (3)
  EXPECT_EQ(a.face(2), b.face(3));
  EXPECT_NE(a.face(2), a.face(3));
  EXPECT_EQ(a.face(2).plane(), 3u * lattice.step(3));
  // Edge 8 of a (corners 1-5, x = 1, y = 0) is edge 10 of b (corners 0-4).
  EXPECT_EQ(a.edge(8), b.edge(10));
  EXPECT_EQ(a.face_centre_half(2), b.face_centre_half(3));
  // Child 6 of a cell shares the parent's corner 6.
  const Cell c = a.child(lattice, 6);
  EXPECT_EQ(c.corner(6), a.corner(6));
  EXPECT_EQ(c.corner(0), (LatticePoint{a.lo[0] + a.step / 2, a.lo[1] + a.step / 2, a.lo[2] + a.step / 2}));
  EXPECT_EQ(c.corner_half(0), a.centre_half());
}

TEST(CellTests, SignChangesFollowTheSignRule) {
  const std::vector<double> none{1.0, 2.0};
  const std::vector<double> two{-1.0, 0.5};
  EXPECT_EQ(sign_changes(1.0, none, 3.0), 0);
  EXPECT_EQ(sign_changes(1.0, two, 3.0), 2);
  EXPECT_EQ(sign_changes(-1.0, none, 3.0), 1);
  const std::vector<double> zero{0.0};
  EXPECT_EQ(sign_changes(1.0, zero, 2.0), 0);  // 0 counts as positive
  EXPECT_EQ(sign_changes(-1.0, zero, -2.0), 2);
}

TEST(CellTests, InPlaneGradients) {
  const std::vector<Vec3> agree{Vec3(1, 0.2, 5), Vec3(1, -0.3, -5), Vec3(0.5, 0.5, 0)};
  EXPECT_TRUE(in_plane_gradients_agree(agree, 2));
  EXPECT_FALSE(in_plane_gradients_agree(agree, 0));  // in the x = const plane (0.2, 5) and (-0.3, -5) oppose
  const std::vector<Vec3> vanishing{Vec3(1, 0, 0), Vec3(0, 0, 3)};
  EXPECT_FALSE(in_plane_gradients_agree(vanishing, 2));
  // A gradient that is not finite (sqrt at the edge of its domain) fails the test.
  const std::vector<Vec3> infinite{Vec3(1, 0.2, 5), Vec3(INFINITY, 0.1, 0)};
  EXPECT_FALSE(in_plane_gradients_agree(infinite, 2));
}

TEST(CellTests, NormalCone) {
  const std::vector<Vec3> narrow{Vec3(1, 0, 0), Vec3(1, 0.5, 0), Vec3(2, 0, -1)};
  EXPECT_TRUE(gradients_within_cone(narrow, 0.5));
  EXPECT_FALSE(gradients_within_cone(narrow, 0.99));
  const std::vector<Vec3> with_zero{Vec3(1, 0, 0), Vec3::Zero()};
  EXPECT_FALSE(gradients_within_cone(with_zero, 0.0));
  const std::vector<Vec3> opposite{Vec3(1, 0, 0), Vec3(-1, 0, 0)};
  EXPECT_FALSE(gradients_within_cone(opposite, 0.0));
  const std::vector<Vec3> not_finite{Vec3(1, 0, 0), Vec3(NAN, 0, 0)};
  EXPECT_FALSE(gradients_within_cone(not_finite, 0.0));
}

TEST(CellTests, NewellNormalOfASquare) {
  const std::vector<Vec3> square{Vec3(5, 5, 1), Vec3(6, 5, 1), Vec3(6, 6, 1), Vec3(5, 6, 1)};
  const Vec3 n = newell_normal(square);
  EXPECT_NEAR(n.x(), 0.0, 1e-12);
  EXPECT_NEAR(n.y(), 0.0, 1e-12);
  EXPECT_NEAR(n.z(), 2.0, 1e-12);  // twice the area
}

}  // namespace
}  // namespace isopatch
