// Two smooth solids united, f = min(a, b) (csg/capped_shape.hpp CutShape::united, api/curved_cut.hpp):
// a lattice with a solid ball in it, read as -max(-a, -b) and meshed as that intersection turned inside
// out; a lattice with a spherical void, max(a, -b), whose operand -b has a closed mesh around an unbounded
// solid. Both capped by the box's planes (closed parts) and cut open by the box; the union of two balls
// inside the box is left to the general crease path.
#include <gtest/gtest.h>

#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/curved_cut.hpp"
#include "csg/capped_shape.hpp"
#include "mesh_checks.hpp"
#include "part_checks.hpp"

namespace isopatch::united_cut_test {
namespace {

const std::string kGyroid = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)";
const std::string kBall = "x^2+y^2+z^2-4";
const std::string kCube = "max(max(abs(x),abs(y)),abs(z))-5";

const std::vector<std::string> kCubeFaces = {"x-5", "-x-5", "y-5", "-y-5", "z-5", "-z-5"};

TEST(UnitedCutShape, AUnionIsReadAsTheComplementOfTheComplementsIntersection) {
  const SurfacePtr f = expression_surface("min(" + kGyroid + "," + kBall + ")", test::cube_box(4.0));
  const std::optional<CutShape> shape = split_cut_shape(*f, test::cube_box(4.0));
  ASSERT_TRUE(shape);
  EXPECT_TRUE(shape->united);
  const Vec3 p(0.3, -0.7, 1.1);
  const double g =
      std::sin(0.3) * std::cos(-0.7) + std::sin(-0.7) * std::cos(1.1) + std::sin(1.1) * std::cos(0.3);
  EXPECT_NEAR(shape->first->value(p), -g, 1e-15);
  EXPECT_NEAR(shape->second->value(p), -(p.squaredNorm() - 4.0), 1e-14);
  // An intersection is not united; a union with a plane, or of three solids, is no cut shape.
  const SurfacePtr both = expression_surface("max(" + kGyroid + ",-(" + kBall + "))", test::cube_box(4.0));
  ASSERT_TRUE(split_cut_shape(*both, test::cube_box(4.0)));
  EXPECT_FALSE(split_cut_shape(*both, test::cube_box(4.0))->united);
  for (const std::string& formula : {"min(" + kGyroid + ",z-1)", "min(" + kGyroid + ",2)"}) {
    const SurfacePtr other = expression_surface(formula, test::cube_box(4.0));
    EXPECT_FALSE(split_cut_shape(*other, test::cube_box(4.0))) << formula;
  }
}

TEST(UnitedCut, AGyroidWithASolidBallCappedByItsBoxIsOneClosedPartOfExactVolume) {
  const test::CappedRun run =
      test::mesh_in_cube("max(min(" + kGyroid + "," + kBall + ")," + kCube + ")", 5.4, 0.25);
  std::vector<std::string> faces = {kGyroid, kBall};
  faces.insert(faces.end(), kCubeFaces.begin(), kCubeFaces.end());
  test::expect_valid_part(run, test::surfaces_in_cube(faces, 5.4), test::cube_box(5.4).diagonal());
  // The gyroid is odd and the cube and ball symmetric: the gyroid's solid holds half of each, and the
  // union is half the cube and half the ball.
  const double exact = 0.5 * (1000.0 + 4.0 / 3.0 * std::numbers::pi * 8.0);
  EXPECT_NEAR(test::enclosed_volume(run.mesh) / exact, 1.0, 2e-3);
}

TEST(UnitedCut, CapsFollowACutCurveThatTurnsWithinTwoEdges) {
  // The Neovius solid with a ball in it, capped by its period box at 1/60 of the side: each cap plane
  // cuts the lattice in curves with tips of radius about 1.6 edges, which the mesher's cells crossed with
  // chords of 3-4 edges (14.5 degrees at the caps); the operands' cuts are now split on the cut curve
  // before the join (api/curved_cut.hpp).
  const std::string neovius = "3*(cos(x)+cos(y)+cos(z))+4*cos(x)*cos(y)*cos(z)";
  const test::CappedRun run =
      test::mesh_in_cube("max(min(" + neovius + ",x*x+y*y+z*z-9),max(max(abs(x),abs(y)),abs(z))-2*pi)", 6.6,
                         4.0 * std::numbers::pi / 60.0);
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_TRUE(t.watertight() && t.manifold() && t.consistently_oriented());
  EXPECT_EQ(test::count_self_intersections(run.mesh, 10), 0u);
  EXPECT_GE(test::min_angle_degrees(run.mesh), 22.0);
  ASSERT_TRUE(run.stats.creases);
  EXPECT_GT(run.stats.creases->caps, 0u);
}

TEST(UnitedCut, AGyroidWithASphericalVoidCappedByItsBoxIsOneClosedPartOfExactVolume) {
  // max(g, -ball): the operand -ball meshes as a closed sphere around an unbounded solid, so the part
  // reaches the box everywhere the lattice does.
  const test::CappedRun run =
      test::mesh_in_cube("max(max(" + kGyroid + ",-(" + kBall + "))," + kCube + ")", 5.4, 0.25);
  std::vector<std::string> faces = {kGyroid, kBall};
  faces.insert(faces.end(), kCubeFaces.begin(), kCubeFaces.end());
  test::expect_valid_part(run, test::surfaces_in_cube(faces, 5.4), test::cube_box(5.4).diagonal());
  const double exact = 0.5 * (1000.0 - 4.0 / 3.0 * std::numbers::pi * 8.0);
  EXPECT_NEAR(test::enclosed_volume(run.mesh) / exact, 1.0, 2e-3);
}

TEST(UnitedCut, AGyroidWithASolidBallCutOpenByTheBoxKeepsItsCreaseAndItsBoundaryOnTheBox) {
  const test::CappedRun run = test::mesh_in_cube("min(" + kGyroid + "," + kBall + ")", 5.0, 0.25);
  const Box box = test::cube_box(5.0);
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_FALSE(t.watertight());
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_EQ(test::count_self_intersections(run.mesh, 10), 0u);
  ASSERT_TRUE(run.stats.creases);
  EXPECT_EQ(run.stats.creases->faces, 2u);
  // Outward: the normals at the ball's face point away from the ball's centre.
  const SurfacePtr gyroid = expression_surface(kGyroid, box), ball = expression_surface(kBall, box);
  std::size_t crease = 0, on_ball = 0, outward = 0;
  for (const Triangle& tri : run.mesh.triangles) {
    const Vec3 &a = run.mesh.positions[tri[0]], &b = run.mesh.positions[tri[1]],
               &c = run.mesh.positions[tri[2]];
    if (std::abs(ball->value(a)) + std::abs(ball->value(b)) + std::abs(ball->value(c)) > 1e-9) continue;
    ++on_ball;
    outward += (b - a).cross(c - a).dot((a + b + c) / 3.0) > 0.0 ? 1 : 0;
  }
  EXPECT_GT(on_ball, 0u);
  EXPECT_EQ(outward, on_ball);
  for (const Vec3& p : run.mesh.positions) {
    const double g = std::abs(gyroid->value(p)) / gyroid->value_gradient(p).gradient.norm();
    const double s = std::abs(ball->value(p)) / ball->value_gradient(p).gradient.norm();
    EXPECT_LT(std::min(g, s), 1e-9 * box.diagonal());
    crease += g < 1e-9 * box.diagonal() && s < 1e-9 * box.diagonal() ? 1 : 0;
  }
  EXPECT_GT(crease, 0u);
  EXPECT_GE(run.stats.creases->crease_vertices, crease);
  // The boundary is where the box cuts the lattice, exactly on its faces.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const Triangle& tri : run.mesh.triangles)
    for (std::size_t k = 0; k < 3; ++k) ++edges[std::minmax(tri[k], tri[(k + 1) % 3])];
  std::size_t boundary = 0;
  for (const auto& [e, n] : edges) {
    if (n != 1) continue;
    ++boundary;
    for (const std::uint32_t v : {e.first, e.second}) {
      const Vec3& p = run.mesh.positions[v];
      EXPECT_EQ(std::min((p - box.lo).cwiseAbs().minCoeff(), (p - box.hi).cwiseAbs().minCoeff()), 0.0)
          << p.transpose();
    }
  }
  EXPECT_GT(boundary, 0u);
}

TEST(UnitedCut, TwoBallsUnitedInsideTheBoxAreLeftToTheGeneralCreasePath) {
  const SurfacePtr f = expression_surface("min(x^2+y^2+z^2-1,(x-1)^2+y^2+z^2-0.6)", test::cube_box(3.0));
  const std::optional<CutShape> shape = split_cut_shape(*f, test::cube_box(3.0));
  ASSERT_TRUE(shape && shape->united);
  Settings s;
  s.box = test::cube_box(3.0);
  s.edge_length = 0.1;
  EXPECT_FALSE(mesh_two_solids(*shape, s, nullptr));
  // The whole run meshes it along its crease, its faces cut into discs (more pieces than faces).
  MeshStats stats;
  const Mesh mesh = mesh_surface(*f, s, &stats);
  EXPECT_TRUE(analyze_topology(mesh).watertight());
  ASSERT_TRUE(stats.creases);
  EXPECT_EQ(stats.creases->creases, 1u);
  EXPECT_GT(stats.creases->pieces, stats.creases->faces);
}

}  // namespace
}  // namespace isopatch::united_cut_test
