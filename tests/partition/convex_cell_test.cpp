// Convex cells from half-spaces (convex_cell.hpp): volumes, faces and planes, nearly parallel and
// nearly coincident planes, degenerate planes and empty intersections.
#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "partition/convex_cell.hpp"

namespace isopatch {
namespace {

const Box kUnit{Vec3::Zero(), Vec3::Ones()};

/// Every face is planar (its vertices on its plane), counter-clockwise about the outward normal, and
/// every edge is shared by exactly two faces in opposite directions (a closed convex polyhedron).
void expect_closed_convex(const ConvexCell& cell) {
  ASSERT_FALSE(cell.empty());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const ConvexCell::Face& f : cell.faces()) {
    const CellPlane& plane = cell.planes()[f.plane];
    ASSERT_GE(f.vertices.size(), 3u);
    Vec3 newell = Vec3::Zero();
    for (std::size_t k = 0; k < f.vertices.size(); ++k) {
      const Vec3& p = cell.vertices()[f.vertices[k]];
      const Vec3& q = cell.vertices()[f.vertices[(k + 1) % f.vertices.size()]];
      EXPECT_LE(std::abs(plane.distance(p)), 1e-12);
      newell += p.cross(q);
      edges.emplace_back(f.vertices[k], f.vertices[(k + 1) % f.vertices.size()]);
    }
    EXPECT_GT(newell.dot(plane.normal), 0.0);
    for (const Vec3& v : cell.vertices()) EXPECT_LE(plane.distance(v), 1e-12);
  }
  for (const auto& [a, b] : edges) {
    int forward = 0, backward = 0;
    for (const auto& [c, d] : edges) {
      forward += (c == a && d == b) ? 1 : 0;
      backward += (c == b && d == a) ? 1 : 0;
    }
    EXPECT_EQ(forward, 1);
    EXPECT_EQ(backward, 1);
  }
}

TEST(ConvexCell, BoxIsAClosedCube) {
  const ConvexCell cell = ConvexCell::box(kUnit, 1e-12);
  expect_closed_convex(cell);
  EXPECT_EQ(cell.faces().size(), 6u);
  EXPECT_EQ(cell.vertices().size(), 8u);
  EXPECT_NEAR(cell.volume(), 1.0, 1e-15);
  EXPECT_NEAR((cell.centroid() - Vec3::Constant(0.5)).norm(), 0.0, 1e-15);
}

TEST(ConvexCell, CornerCutGivesATetrahedronAndItsComplement) {
  // x + y + z <= 1 keeps the tetrahedron of volume 1/6 at the origin.
  const ConvexCell tet = intersect_half_spaces(kUnit, {make_cell_plane(1, 1, 1, -1)});
  expect_closed_convex(tet);
  EXPECT_EQ(tet.faces().size(), 4u);
  EXPECT_NEAR(tet.volume(), 1.0 / 6.0, 1e-15);
  const ConvexCell rest = intersect_half_spaces(kUnit, {make_cell_plane(-1, -1, -1, 1)});
  expect_closed_convex(rest);
  EXPECT_EQ(rest.faces().size(), 7u);  // six box faces, three of them cut, and the cap
  EXPECT_NEAR(rest.volume(), 5.0 / 6.0, 1e-15);
}

TEST(ConvexCell, ManyTangentPlanesApproachABall) {
  // 400 planes tangent to the sphere of radius 0.4 about the centre: volume between the ball's and
  // the cube's, close to the ball's.
  std::vector<CellPlane> planes;
  const Vec3 c = Vec3::Constant(0.5);
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
    const Vec3 u(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    planes.push_back(make_cell_plane(u.x(), u.y(), u.z(), -u.dot(c) - 0.4));
  }
  const ConvexCell ball = intersect_half_spaces(kUnit, planes);
  expect_closed_convex(ball);
  const double exact = 4.0 / 3.0 * std::numbers::pi * 0.064;
  EXPECT_GT(ball.volume(), exact);
  EXPECT_LT(ball.volume(), 1.03 * exact);
  EXPECT_TRUE(ball.contains(c, 0.0));
  EXPECT_FALSE(ball.contains(Vec3(0.02, 0.02, 0.02), 0.0));
}

TEST(ConvexCell, NearlyCoincidentPlanesKeepTheFirst) {
  // Two planes 1e-15 apart (within the tolerance): the second is redundant, one cap.
  const ConvexCell cell =
      intersect_half_spaces(kUnit, {make_cell_plane(0, 0, 1, -0.5), make_cell_plane(0, 0, 1, -0.5 + 1e-15)});
  expect_closed_convex(cell);
  EXPECT_EQ(cell.faces().size(), 6u);
  EXPECT_NEAR(cell.volume(), 0.5, 1e-14);
  // The same plane twice, and a plane through existing vertices only, change nothing either.
  const ConvexCell twice =
      intersect_half_spaces(kUnit, {make_cell_plane(1, 1, 0, -1), make_cell_plane(1, 1, 0, -1)});
  expect_closed_convex(twice);
  EXPECT_EQ(twice.faces().size(), 5u);
  EXPECT_NEAR(twice.volume(), 0.5, 1e-14);
}

TEST(ConvexCell, NearlyParallelPlanesMeetInAThinWedge) {
  // z <= 0.5 and a plane tilted by 1e-7 rad through the same line x = 0: a wedge of 1e-7 / 2 thickness
  // at x = 1 is cut away, and the cell stays closed and convex.
  const double t = 1e-7;
  const ConvexCell cell = intersect_half_spaces(
      kUnit,
      {make_cell_plane(0, 0, 1, -0.5), make_cell_plane(std::sin(t), 0, std::cos(t), -0.5 * std::cos(t))});
  expect_closed_convex(cell);
  EXPECT_NEAR(cell.volume(), 0.5 - 0.5 * std::tan(t) * 1.0, 1e-13);
  // Nearly parallel and nearly coincident: the tilt at x = 1 is below the tolerance, so redundant.
  const double tiny = 1e-14;
  const ConvexCell same = intersect_half_spaces(
      kUnit, {make_cell_plane(0, 0, 1, -0.5), make_cell_plane(std::sin(tiny), 0, std::cos(tiny), -0.5)});
  expect_closed_convex(same);
  EXPECT_EQ(same.faces().size(), 6u);
}

TEST(ConvexCell, EmptyAndDegenerateIntersectionsAreErrors) {
  // Disjoint half-spaces.
  EXPECT_THROW(intersect_half_spaces(kUnit, {make_cell_plane(0, 0, 1, -0.2), make_cell_plane(0, 0, -1, 0.6)}),
               InputError);
  // Outside the box.
  EXPECT_THROW(intersect_half_spaces(kUnit, {make_cell_plane(1, 0, 0, 2)}), InputError);
  // Two opposite planes through the same point: only a flat slab of no volume is left.
  EXPECT_THROW(intersect_half_spaces(kUnit, {make_cell_plane(1, 0, 0, -0.5), make_cell_plane(-1, 0, 0, 0.5)}),
               InputError);
  // Planes without a normal or with a non-finite coefficient.
  EXPECT_THROW(make_cell_plane(0, 0, 0, 1), InputError);
  EXPECT_THROW(make_cell_plane(std::nan(""), 0, 1, 0), InputError);
  EXPECT_THROW(make_cell_plane(1, 0, 0, INFINITY), InputError);
  EXPECT_THROW(ConvexCell::box(Box{Vec3::Zero(), Vec3(1, 0, 1)}, 1e-12), InputError);
  try {
    intersect_half_spaces(kUnit, {make_cell_plane(0, 0, 1, 3)});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
  }
}

TEST(ConvexCell, SharedEdgesAreCutToTheSameBits) {
  // Two unit cubes side by side, both clipped by one oblique plane: the vertices on their shared face
  // are bit-identical (the crossing of an edge is interpolated from its lexicographically smaller end).
  const CellPlane plane = make_cell_plane(0.3, 0.7, 1.0, -1.1);
  ConvexCell a = ConvexCell::box(kUnit, 1e-12), b = ConvexCell::box(Box{Vec3(1, 0, 0), Vec3(2, 1, 1)}, 1e-12);
  ASSERT_TRUE(a.clip(plane));
  ASSERT_TRUE(b.clip(plane));
  int shared = 0;
  for (const Vec3& p : a.vertices())
    if (p.x() == 1.0)
      for (const Vec3& q : b.vertices()) shared += p == q ? 1 : 0;
  int on_face = 0;
  for (const Vec3& p : a.vertices()) on_face += p.x() == 1.0 ? 1 : 0;
  EXPECT_EQ(shared, on_face);
  EXPECT_GE(on_face, 3);
}

}  // namespace
}  // namespace isopatch
