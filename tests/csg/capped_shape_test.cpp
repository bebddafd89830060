// Smooth solids capped by a convex polyhedron (csg/capped_shape.hpp, api/capped_meshing.hpp): the
// formula's split into the smooth operand and the planes, and the lattice parts meshed as the cut
// surface closed by planar caps: closed, manifold, outward, free of self-intersections, every vertex
// on f = 0, every crease vertex on both of its faces, mostly valence 6, the same bytes for any thread
// count; the general crease path (which cannot cut a gyroid's face into discs) kept for the rest.
#include <gtest/gtest.h>

#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/triangle_angle.hpp"
#include "csg/capped_shape.hpp"
#include "mesh_checks.hpp"
#include "part_checks.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

const std::string kCapGyroid = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)";
const std::string kCapSchwarzP = "cos(x)+cos(y)+cos(z)";
const std::string kCapBox = "max(max(abs(x),abs(y)),abs(z))-pi";

Box capped_box(double a) {
  return {Vec3::Constant(-a), Vec3::Constant(a)};
}

std::optional<CappedShape> split(const std::string& formula) {
  const SurfacePtr f = expression_surface(formula, capped_box(4.0));
  return split_capped_shape(*f, capped_box(4.0));
}

TEST(CappedShape, ABoxCappingALatticeGivesTheLatticeAndSixPlanes) {
  const auto shape = split("max(" + kCapGyroid + "," + kCapBox + ")");
  ASSERT_TRUE(shape);
  ASSERT_EQ(shape->planes.size(), 6u);
  for (const HalfSpace& h : shape->planes) {
    EXPECT_NEAR(std::hypot(h.a, h.b, h.c), 1.0, 1e-15);
    EXPECT_NEAR(h.d, -std::numbers::pi, 1e-12);
  }
  const Vec3 p(0.3, -0.7, 1.1);
  EXPECT_NEAR(shape->smooth->value(p),
              std::sin(0.3) * std::cos(-0.7) + std::sin(-0.7) * std::cos(1.1) + std::sin(1.1) * std::cos(0.3),
              1e-15);
}

TEST(CappedShape, ASheetIsOneSmoothOperandAndScalingKeepsThePlanes) {
  // abs(g) - t: the abs of a curved operand is not split (its tie lies inside the sheet).
  const auto sheet = split("2*max(abs(" + kCapGyroid + ")-0.3,max(x-1,-x-1)+0.5)");
  ASSERT_TRUE(sheet);
  ASSERT_EQ(sheet->planes.size(), 2u);
  EXPECT_NEAR(sheet->planes[0].d, -0.5, 1e-15);
  EXPECT_NEAR(sheet->smooth->value(Vec3(0.1, 0.2, 0.3)) / 2.0,
              std::abs(std::sin(0.1) * std::cos(0.2) + std::sin(0.2) * std::cos(0.3) +
                       std::sin(0.3) * std::cos(0.1)) -
                  0.3,
              1e-15);
}

TEST(CappedShape, OtherFormulasAreNotCappedShapes) {
  const auto polyhedron = split(kCapBox);  // planes only
  ASSERT_TRUE(polyhedron);
  EXPECT_FALSE(polyhedron->smooth);
  EXPECT_EQ(polyhedron->planes.size(), 6u);
  EXPECT_FALSE(split(kCapGyroid));                                    // no plane
  EXPECT_FALSE(split("min(" + kCapGyroid + "," + kCapBox + ")"));     // a union
  EXPECT_FALSE(split("max(max(" + kCapGyroid + ",x-1),x^2+y^2-1)"));  // two curved operands
  // A curved operand with no plane under it is one operand (its own creases are the analysis' matter).
  const auto joined = split("max(max(" + kCapGyroid + ",x^2+y^2-1)," + kCapBox + ")");
  ASSERT_TRUE(joined);
  EXPECT_EQ(joined->planes.size(), 6u);
  EXPECT_FALSE(split("-max(" + kCapGyroid + "," + kCapBox + ")"));  // decreasing
  EXPECT_FALSE(split("max(" + kCapGyroid + ",-2)"));                // a constant operand
}

/// The formula meshed in the cube of half-side `box` with `s` (its box set).
test::CappedRun mesh_capped(const std::string& formula, double box, Settings s) {
  test::CappedRun run;
  run.surface = expression_surface(formula, capped_box(box));
  s.box = capped_box(box);
  run.mesh = mesh_surface(*run.surface, s, &run.stats);
  return run;
}

test::CappedRun mesh_capped(const std::string& formula, double box, double edge, int threads = 0) {
  Settings s;
  s.edge_length = edge;
  s.threads = threads;
  return mesh_capped(formula, box, s);
}

std::vector<SurfacePtr> faces_of(const std::string& smooth, const Box& box) {
  std::vector<SurfacePtr> faces{expression_surface(smooth, box)};
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      const std::string c(1, "xyz"[axis]);
      faces.push_back(expression_surface((side > 0 ? c : "-" + c) + "-pi", box));
    }
  return faces;
}

TEST(CappedLattice, AGyroidCappedByItsBoxIsAClosedPartAlongItsCreases) {
  // The box through the gyroid's zeros at its corners and edge midpoints (whole half periods): the
  // cut vertices there are the polyhedron's corners.
  const test::CappedRun run = mesh_capped("max(" + kCapGyroid + "," + kCapBox + ")", 3.3, 0.21);
  test::expect_valid_part(run, faces_of(kCapGyroid, capped_box(3.3)), capped_box(3.3).diagonal());
  EXPECT_EQ(run.stats.creases->caps, 6u);
}

TEST(CappedLattice, ASchwarzPSheetCappedByItsBoxIsAClosedPart) {
  const std::string sheet = "abs(" + kCapSchwarzP + ")-0.4";
  const test::CappedRun run = mesh_capped("max(" + sheet + "," + kCapBox + ")", 3.3, 0.2);
  test::expect_valid_part(run, faces_of(sheet, capped_box(3.3)), capped_box(3.3).diagonal());
}

TEST(CappedLattice, AnErrorBoundGradesTheCutAndTheCapsFollowIt) {
  // With an error bound the cut's edges are shorter than the largest size where it meets the box: the
  // caps take the cut's mean edge, so no triangle at the creases spans the two sizes.
  Settings s;
  s.max_error = 0.01;
  const test::CappedRun run = mesh_capped("max(" + kCapGyroid + "," + kCapBox + ")", 3.3, s);
  test::expect_valid_part(run, faces_of(kCapGyroid, capped_box(3.3)), capped_box(3.3).diagonal());
}

TEST(CappedLattice, TheVolumeConvergesAndTheTopologyHolds) {
  // Schwarz P capped by the box of one period: half the cube is solid by symmetry (f(-p - pi) = -f(p)).
  const std::string part = "max(" + kCapSchwarzP + "," + kCapBox + ")";
  const test::CappedRun coarse = mesh_capped(part, 3.3, 0.2);
  const test::CappedRun fine = mesh_capped(part, 3.3, 0.1);
  const double half = 0.5 * std::pow(2.0 * std::numbers::pi, 3);
  EXPECT_NEAR(test::enclosed_volume(coarse.mesh) / half, 1.0, 2e-3);
  EXPECT_NEAR(test::enclosed_volume(fine.mesh) / half, 1.0, 5e-4);
  EXPECT_EQ(analyze_topology(coarse.mesh).genus, analyze_topology(fine.mesh).genus);
  EXPECT_EQ(analyze_topology(coarse.mesh).components.size(), analyze_topology(fine.mesh).components.size());
}

TEST(CappedLattice, TheSameBytesForOneAndTwoThreads) {
  const std::string part = "max(" + kCapGyroid + "," + kCapBox + ")";
  const test::CappedRun one = mesh_capped(part, 3.3, 0.25, 1);
  const test::CappedRun two = mesh_capped(part, 3.3, 0.25, 2);
  ASSERT_EQ(one.mesh.positions.size(), two.mesh.positions.size());
  EXPECT_EQ(one.mesh.positions, two.mesh.positions);
  EXPECT_EQ(one.mesh.triangles, two.mesh.triangles);
}

TEST(CappedLattice, CreasesOffMeshesTheFormulaAsASmoothSurface) {
  Settings s;
  s.edge_length = 0.3;
  s.creases = Creases::Off;
  const test::CappedRun run = mesh_capped("max(" + kCapSchwarzP + "," + kCapBox + ")", 3.0, s);
  EXPECT_FALSE(run.stats.creases);
}

TEST(CappedLattice, APolyhedronLeavingTheBoxIsCutOpenByItWithItsCreasesExact) {
  // A gyroid under the plane z = 1 in a box the plane does not close: the box cuts the part open.
  const std::string part = "max(" + kCapGyroid + ",z-1)";
  const test::CappedRun run = mesh_capped(part, 3.0, 0.15);
  ASSERT_TRUE(run.stats.creases);
  EXPECT_EQ(run.stats.creases->caps, 1u);
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_GT(t.boundary_edges, 0u);
  EXPECT_TRUE(t.manifold() && t.consistently_oriented());
  EXPECT_EQ(test::count_self_intersections(run.mesh, 10), 0u);
  const double diagonal = capped_box(3.0).diagonal();
  EXPECT_LT(test::max_vertex_distance(*run.surface, run.mesh), 1e-9 * diagonal);
  for (std::uint32_t v : test::boundary_vertices(run.mesh)) {
    const Vec3& p = run.mesh.positions[v];
    EXPECT_LT((p.cwiseAbs() - Vec3::Constant(3.0)).cwiseAbs().minCoeff(), 1e-12)
        << "boundary vertex off the box";
  }
  // The crease z = 1: every vertex on the plane and on the gyroid is on both.
  const std::vector<SurfacePtr> faces{expression_surface(kCapGyroid, capped_box(3.0)),
                                      expression_surface("z-1", capped_box(3.0))};
  std::size_t crease = 0;
  for (const Vec3& p : run.mesh.positions)
    if (std::abs(p.z() - 1.0) < 1e-9 && std::abs(faces[0]->value(p)) < 1e-6) {
      ++crease;
      EXPECT_LT(std::abs(faces[0]->value(p)) / faces[0]->value_gradient(p).gradient.norm(), 1e-9 * diagonal);
    }
  EXPECT_GT(crease, 20u);
  EXPECT_GE(test::min_angle_degrees(run.mesh), 25.0);
}

/// Vertices on two or more of the unit cube's faces (its creases and corners).
std::size_t cube_crease_vertices(const Mesh& mesh) {
  std::size_t count = 0;
  for (const Vec3& p : mesh.positions) {
    int faces = 0;
    for (int axis = 0; axis < 3; ++axis) faces += std::abs(std::abs(p[axis]) - 1.0) < 1e-12 ? 1 : 0;
    count += faces >= 2 ? 1 : 0;
  }
  return count;
}

/// The unit cube's formula in its box, and settings at edge 0.1 there.
const std::string kUnitCube = "max(max(abs(x),abs(y)),abs(z))-1";
Settings unit_cube_settings() {
  Settings s;
  s.box = capped_box(1.5);
  s.edge_length = 0.1;
  return s;
}

TEST(CappedLattice, ACubeClippedByARegionHalfSpaceKeepsItsCreasesAndItsCut) {
  const SurfacePtr f = expression_surface(kUnitCube, capped_box(1.5));
  Settings s = unit_cube_settings();
  s.region = {HalfSpace{2.0, 0.0, 0.0, -1.0}};  // 2 x - 1 <= 0: x <= 0.5, a normal that is not unit
  MeshStats stats;
  const Mesh mesh = mesh_surface(*f, s, &stats);
  ASSERT_TRUE(stats.creases);
  EXPECT_EQ(stats.creases->caps, 5u);  // the face x = 1 lies outside the region
  EXPECT_EQ(stats.warnings.creases_in_partition, 0u);
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_GT(t.boundary_edges, 0u);
  EXPECT_TRUE(t.manifold() && t.consistently_oriented());
  for (std::uint32_t v : test::boundary_vertices(mesh)) EXPECT_NEAR(mesh.positions[v].x(), 0.5, 1e-12);
  // The cube's eight edges inside the region, exactly: on two faces to rounding.
  for (const Vec3& p : mesh.positions) EXPECT_LE(p.x(), 0.5 + 1e-12);
  EXPECT_GT(cube_crease_vertices(mesh), 50u);
  EXPECT_GE(test::min_angle_degrees(mesh), 25.0);
  EXPECT_EQ(test::count_self_intersections(mesh, 10), 0u);
}

TEST(CappedLattice, ALatticeShelledByItsBoxIsTheBoxAndItsHollowsAlongTheCreases) {
  // min(max(P, box), max(box, inner - box)): Schwarz P inside the box of one period, a skin from there
  // to the box of half-side 3.5. The hollows (P > 0 inside the inner box) are half of it by symmetry.
  const std::string outer = "max(max(abs(x),abs(y)),abs(z))-3.5";
  const std::string part =
      "min(max(" + kCapSchwarzP + "," + outer + "),max(" + outer + ",pi-max(max(abs(x),abs(y)),abs(z))))";
  const std::optional<ShelledShape> split_part =
      split_shelled_shape(*expression_surface(part, capped_box(4.0)), capped_box(4.0));
  ASSERT_TRUE(split_part);
  EXPECT_EQ(split_part->outer.size(), 6u);
  EXPECT_EQ(split_part->inner.size(), 6u);
  const test::CappedRun run = mesh_capped(part, 4.0, 0.2);
  ASSERT_TRUE(run.stats.creases);
  EXPECT_EQ(run.stats.creases->caps, 12u);
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_TRUE(t.watertight() && t.manifold() && t.consistently_oriented());
  EXPECT_EQ(t.components.size(), 2u);  // the box's skin and the hollows' surface inside it
  EXPECT_EQ(test::count_self_intersections(run.mesh, 10), 0u);
  EXPECT_LT(test::max_vertex_distance(*run.surface, run.mesh), 1e-9 * capped_box(4.0).diagonal());
  const double expected = 7.0 * 7.0 * 7.0 - 0.5 * std::pow(2.0 * std::numbers::pi, 3);
  EXPECT_NEAR(test::enclosed_volume(run.mesh) / expected, 1.0, 2e-3);
  EXPECT_GE(test::min_angle_degrees(run.mesh), 25.0);
}

TEST(CappedLattice, ACubeInARotatedFrameKeepsItsCreasesAndItsVolume) {
  const SurfacePtr f = expression_surface(kUnitCube, capped_box(1.5));
  Settings s = unit_cube_settings();
  MeshStats plain_stats;
  const Mesh plain = mesh_surface(*f, s, &plain_stats);
  s.frame = Frame{30.0, 20.0, 10.0};
  MeshStats turned_stats;
  const Mesh turned = mesh_surface(*f, s, &turned_stats);
  ASSERT_TRUE(turned_stats.creases);
  EXPECT_EQ(turned_stats.creases->caps, 6u);
  EXPECT_EQ(turned_stats.warnings.creases_in_partition, 0u);
  const TopologyReport t = analyze_topology(turned);
  EXPECT_TRUE(t.watertight() && t.manifold() && t.consistently_oriented());
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_NEAR(test::enclosed_volume(turned) / 8.0, 1.0, 1e-12);
  const double with = static_cast<double>(cube_crease_vertices(turned));
  const double without = static_cast<double>(cube_crease_vertices(plain));
  EXPECT_NEAR(with / without, 1.0, 0.05);
  EXPECT_GE(test::min_angle_degrees(turned), 25.0);
  EXPECT_EQ(test::count_self_intersections(turned, 10), 0u);
}

TEST(CappedLattice, AFrameKeepsTheCreasesOfAnyCsgShape) {
  // Two boxes side by side (a union: not a capped solid) in a frame: the crease path has no partition to
  // turn, so the mesh along the creases is the one without the frame, and nothing is said.
  const std::string boxes =
      "min(max(max(abs(x),abs(y)),abs(z))-1,max(max(abs(x-1.5),abs(y)),abs(z-0.3))-0.5)";
  const Box box{Vec3(-1.5, -1.5, -1.5), Vec3(2.5, 1.5, 1.5)};
  const SurfacePtr f = expression_surface(boxes, box);
  Settings s;
  s.box = box;
  s.edge_length = 0.15;
  const Mesh plain = mesh_surface(*f, s);
  s.frame = Frame{30.0, 20.0, 10.0};
  MeshStats stats;
  const Mesh turned = mesh_surface(*f, s, &stats);
  ASSERT_TRUE(stats.creases);
  EXPECT_GT(stats.creases->creases, 12u);
  EXPECT_EQ(stats.warnings.creases_in_partition, 0u);
  EXPECT_EQ(turned.positions, plain.positions);
  EXPECT_EQ(turned.triangles, plain.triangles);
  // A smooth formula in a frame has nothing to say.
  const SurfacePtr sphere = expression_surface("x^2+y^2+z^2-1", capped_box(1.5));
  s.box = capped_box(1.5);
  MeshStats smooth_stats;
  mesh_surface(*sphere, s, &smooth_stats);
  EXPECT_FALSE(smooth_stats.creases);
  EXPECT_EQ(smooth_stats.warnings.creases_in_partition, 0u);
}

}  // namespace
}  // namespace isopatch
