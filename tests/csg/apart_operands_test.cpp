// Two solids whose surfaces never meet (csg/apart_operands.hpp, api/apart_meshing.hpp): a gyroid lattice
// inside a spherical skin, max(outer, min(gyroid, -inner)), and two capped lattices side by side, each
// operand meshed by its own path and the components the other solid keeps joined; what is not split
// (surfaces that meet, share a face, come closer than the proof looks, or a smooth formula).
#include <gtest/gtest.h>

#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "csg/apart_operands.hpp"
#include "mesh_checks.hpp"
#include "part_checks.hpp"

namespace isopatch::apart_operands_test {
namespace {

const std::string kGyroid = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)";
const std::string kRadius = "sqrt(x^2+y^2+z^2)";
// A gyroid lattice filling a ball of radius 4.5 inside a skin 0.5 thick: solid where r < 5 and either
// the gyroid's solid or the skin (r > 4.5).
const std::string kSkinned = "max(" + kRadius + "-5,min(" + kGyroid + ",4.5-" + kRadius + "))";

std::optional<ApartOperands> split(const std::string& formula, double a, double finest) {
  const SurfacePtr f = expression_surface(formula, test::cube_box(a));
  return split_apart_operands(*f, test::cube_box(a), finest);
}

TEST(ApartOperands, ALatticeInsideACurvedSkinIsItsSkinAndItsHollowedLattice) {
  const std::optional<ApartOperands> shape = split(kSkinned, 5.4, 0.06);
  ASSERT_TRUE(shape);
  EXPECT_FALSE(shape->united);
  const Vec3 p(0.3, -0.7, 1.1);
  const double g =
      std::sin(0.3) * std::cos(-0.7) + std::sin(-0.7) * std::cos(1.1) + std::sin(1.1) * std::cos(0.3);
  EXPECT_NEAR(shape->operands[0]->value(p), p.norm() - 5.0, 1e-14);
  EXPECT_NEAR(shape->operands[1]->value(p), std::min(g, 4.5 - p.norm()), 1e-14);
  // A union of two capped lattices far apart is split as a union.
  const std::string left = "max(" + kGyroid + ",max(max(abs(x+3),abs(y)),abs(z))-2)";
  const std::string right = "max(" + kGyroid + ",max(max(abs(x-3),abs(y)),abs(z))-2)";
  const std::optional<ApartOperands> pair = split("min(" + left + "," + right + ")", 5.4, 0.06);
  ASSERT_TRUE(pair);
  EXPECT_TRUE(pair->united);
}

TEST(ApartOperands, AnInfillAndASkinUnitedAreFactoredOverTheBodyTheyShare) {
  // min(max(X, T), max(T, Y)) = max(T, min(X, Y)): the lattice in the body united with the body less its
  // offset is the body intersected with the lattice united with the offset's complement.
  const std::string body = kRadius + "-5";
  const std::optional<ApartOperands> shape =
      split("2*min(max(" + kGyroid + "," + body + "),max(" + body + ",4.5-" + kRadius + "))", 5.4, 0.06);
  ASSERT_TRUE(shape);
  EXPECT_FALSE(shape->united);
  // And max(min(X, T), min(T, Y)) = min(T, max(X, Y)): a ball apart from the gyroid cut by another.
  const std::string ball = "(x-4)^2+y^2+z^2-1";
  const std::optional<ApartOperands> dual =
      split("max(min(" + kGyroid + "," + ball + "),min(" + ball + "," + kRadius + "-2))", 5.4, 0.06);
  ASSERT_TRUE(dual);
  EXPECT_TRUE(dual->united);
  for (const Vec3& p : {Vec3(0.3, -0.7, 1.1), Vec3(4.2, 0.1, -0.3), Vec3(-2.5, 3.0, 1.9)}) {
    const double g = std::sin(p.x()) * std::cos(p.y()) + std::sin(p.y()) * std::cos(p.z()) +
                     std::sin(p.z()) * std::cos(p.x());
    const double r = p.norm(), b = (p.x() - 4) * (p.x() - 4) + p.y() * p.y() + p.z() * p.z() - 1;
    EXPECT_NEAR(shape->operands[0]->value(p), 2 * (r - 5), 1e-13);
    EXPECT_NEAR(shape->operands[1]->value(p), 2 * std::min(g, 4.5 - r), 1e-13);
    EXPECT_NEAR(dual->operands[0]->value(p), b, 1e-13);
    EXPECT_NEAR(dual->operands[1]->value(p), std::max(g, r - 2), 1e-13);
  }
}

TEST(ApartOperands, AnInfillOfTheSkinsInnerBodyIsReadWithoutTheFaceTheyShare) {
  // min(max(X, s), max(t, -s)) with s < 0 inside t < 0: the solid of max(t, min(X, -s)); f itself vanishes
  // on the inner sphere where X < 0 without changing sign there.
  for (const std::string& formula :
       {"min(max(" + kGyroid + "," + kRadius + "-4.5),max(" + kRadius + "-5,4.5-" + kRadius + "))",
        "min(max(" + kRadius + "-5,-(" + kRadius + "-4.5)),max(" + kRadius + "-4.5," + kGyroid + "))"}) {
    const std::optional<ApartOperands> shape = split(formula, 5.4, 0.06);
    ASSERT_TRUE(shape) << formula;
    EXPECT_FALSE(shape->united);
    for (const Vec3& p : {Vec3(0.3, -0.7, 1.1), Vec3(4.2, 0.1, -0.3), Vec3(-2.5, 3.0, 1.9)}) {
      const double g = std::sin(p.x()) * std::cos(p.y()) + std::sin(p.y()) * std::cos(p.z()) +
                       std::sin(p.z()) * std::cos(p.x());
      EXPECT_NEAR(shape->operands[0]->value(p), p.norm() - 5.0, 1e-13);
      EXPECT_NEAR(shape->operands[1]->value(p), std::min(g, 4.5 - p.norm()), 1e-13);
    }
  }
}

TEST(ApartOperands, SurfacesThatMeetShareAFaceOrComeTooCloseAreNotSplit) {
  // The lattice reaches the outer sphere: a crease between the operands.
  EXPECT_FALSE(split("max(" + kRadius + "-4,min(" + kGyroid + ",4.5-" + kRadius + "))", 5.4, 0.06));
  // An infill of the ball r < 5 united with the ball of radius 5.8 about (1, 0, 0) less the ball r < 5:
  // the infill pokes out of the outer ball at (-5, 0, 0), so r = 5 is no inner face throughout.
  EXPECT_FALSE(
      split("min(max(" + kGyroid + "," + kRadius + "-5),max(sqrt((x-1)^2+y^2+z^2)-5.8,5-" + kRadius + "))",
            5.4, 0.06));
  // Surfaces 0.02 apart, closer than the proof's finest boxes of 0.06.
  EXPECT_FALSE(split("max(" + kRadius + "-5,min(" + kGyroid + ",4.98-" + kRadius + "))", 5.4, 0.06));
  // Two balls apart are smooth where f vanishes: meshed whole.
  EXPECT_FALSE(split("min(x^2+y^2+z^2-1,(x-3)^2+y^2+z^2-1)", 5.4, 0.06));
  // The root is not a max or min.
  EXPECT_FALSE(split("2-max(" + kRadius + "-5,min(" + kGyroid + ",4.5-" + kRadius + "))", 5.4, 0.06));
}

TEST(ApartOperandsMeshing, ALatticeInsideACurvedSkinIsMeshedAlongItsCreasesWithExactVolume) {
  const test::CappedRun run = test::mesh_in_cube(kSkinned, 5.4, 0.25);
  test::expect_valid_part(run, test::surfaces_in_cube({kRadius + "-5", kGyroid, kRadius + "-4.5"}, 5.4),
                          test::cube_box(5.4).diagonal(), false);
  // The skin's outer sphere and the lattice's hollowed surface, the lattice's crease with the skin.
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_EQ(t.components.size(), 2u);
  ASSERT_TRUE(run.stats.creases);
  EXPECT_GT(run.stats.creases->crease_vertices, 0u);
  EXPECT_EQ(run.stats.warnings.creases_rounded, 0u);
  // The gyroid is odd: its solid holds half of the inner ball, so the part is the outer ball less half of
  // the inner one.
  const double exact = 4.0 / 3.0 * std::numbers::pi * (125.0 - 0.5 * 91.125);
  EXPECT_NEAR(test::enclosed_volume(run.mesh) / exact, 1.0, 2e-3);
  // The same bytes on one thread as on the default number.
  const test::CappedRun one = test::mesh_in_cube(kSkinned, 5.4, 0.25, 1);
  EXPECT_EQ(one.mesh.positions, run.mesh.positions);
  EXPECT_EQ(one.mesh.triangles, run.mesh.triangles);
}

TEST(ApartOperandsMeshing, TheSkinWrittenAsAUnionWithTheInfillGivesTheSameMeshEitherWay) {
  const std::string body = kRadius + "-5";
  const test::CappedRun united = test::mesh_in_cube(
      "min(max(" + kGyroid + "," + body + "),max(" + body + ",4.5-" + kRadius + "))", 5.4, 0.25);
  const test::CappedRun direct = test::mesh_in_cube(kSkinned, 5.4, 0.25);
  EXPECT_EQ(united.mesh.positions, direct.mesh.positions);
  EXPECT_EQ(united.mesh.triangles, direct.mesh.triangles);
  EXPECT_EQ(united.stats.warnings.creases_rounded, 0u);
  // The infill of the inner ball united with the skin: the same solid, the same mesh.
  const test::CappedRun infill = test::mesh_in_cube(
      "min(max(" + kGyroid + "," + kRadius + "-4.5),max(" + kRadius + "-5,4.5-" + kRadius + "))", 5.4, 0.25);
  EXPECT_EQ(infill.mesh.positions, direct.mesh.positions);
  EXPECT_EQ(infill.mesh.triangles, direct.mesh.triangles);
}

TEST(ApartOperandsMeshing, ALatticeInsideABoxSkinIsTheSkinAndTheCappedHollowsTurnedOver) {
  // max(M - 3.3, min(g, 2.9 - M)): the outer cube apart from min(g, 2.9 - M), the union of the lattice
  // with the outside of the inner cube, meshed as the capped solid max(-g, M - 2.9) turned over.
  const std::string cube = "max(max(abs(x),abs(y)),abs(z))";
  const test::CappedRun run =
      test::mesh_in_cube("max(" + cube + "-3.3,min(" + kGyroid + ",2.9-" + cube + "))", 3.6, 0.15);
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_TRUE(t.watertight() && t.manifold() && t.consistently_oriented());
  EXPECT_EQ(t.components.size(), 2u);
  EXPECT_EQ(test::count_self_intersections(run.mesh, 10), 0u);
  EXPECT_LT(test::max_vertex_distance(*run.surface, run.mesh), 1e-9 * test::cube_box(3.6).diagonal());
  EXPECT_GE(test::min_angle_degrees(run.mesh), 25.0);
  const std::vector<int> valence = test::valences(run.mesh);
  EXPECT_GE(static_cast<double>(std::count(valence.begin(), valence.end(), 6)) /
                static_cast<double>(valence.size()),
            0.9);
  // The hollows' caps on the inner cube (the outer cube is the general path's, its faces pieces).
  ASSERT_TRUE(run.stats.creases);
  EXPECT_EQ(run.stats.creases->caps, 6u);
  EXPECT_EQ(run.stats.warnings.creases_rounded, 0u);
  // Every vertex on the lattice and an inner face is on both, exactly.
  const SurfacePtr gyroid = expression_surface(kGyroid, test::cube_box(3.6));
  std::size_t crease = 0;
  for (const Vec3& p : run.mesh.positions) {
    if (std::abs(p.cwiseAbs().maxCoeff() - 2.9) > 1e-12) continue;
    crease += std::abs(gyroid->value(p)) < 1e-9 ? 1 : 0;
  }
  EXPECT_GT(crease, 100u);
  // The outer cube less half the inner one (the gyroid is odd).
  const double exact = std::pow(6.6, 3) - 0.5 * std::pow(5.8, 3);
  EXPECT_NEAR(test::enclosed_volume(run.mesh) / exact, 1.0, 2e-3);
}

TEST(ApartOperandsMeshing, TwoCappedLatticesSideBySideAreTwoClosedPartsOfExactVolume) {
  // Cubes of side 4 about (+-2 pi, 0, 0), centres of symmetry of the gyroid: each holds half its cube.
  const std::string left = "max(" + kGyroid + ",max(max(abs(x+2*pi),abs(y)),abs(z))-2)";
  const std::string right = "max(" + kGyroid + ",max(max(abs(x-2*pi),abs(y)),abs(z))-2)";
  const test::CappedRun run = test::mesh_in_cube("min(" + left + "," + right + ")", 8.7, 0.25);
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_EQ(test::count_self_intersections(run.mesh, 10), 0u);
  EXPECT_GE(test::min_angle_degrees(run.mesh), 25.0);
  ASSERT_TRUE(run.stats.creases);
  EXPECT_EQ(run.stats.creases->caps, 12u);
  EXPECT_NEAR(test::enclosed_volume(run.mesh) / 64.0, 1.0, 2e-3);
  // Each part closed on its own, half its cube.
  Mesh left_part = run.mesh;
  std::erase_if(left_part.triangles,
                [&](const Triangle& tri) { return run.mesh.positions[tri[0]].x() > 0.0; });
  EXPECT_TRUE(analyze_topology(left_part).watertight());
  EXPECT_NEAR(test::enclosed_volume(left_part) / 32.0, 1.0, 2e-3);
}

TEST(ApartOperandsMeshing, AnIntersectionOfSolidsApartIsNoSurface) {
  // A ball and a capped lattice far from it: their intersection is empty.
  const SurfacePtr f = expression_surface(
      "max(" + kRadius + "-1,max(" + kGyroid + ",max(max(abs(x-5),abs(y)),abs(z))-2))", test::cube_box(7.4));
  Settings s;
  s.box = test::cube_box(7.4);
  s.edge_length = 0.25;
  EXPECT_THROW(mesh_surface(*f, s, nullptr), NoSurfaceError);
}

}  // namespace
}  // namespace isopatch::apart_operands_test
