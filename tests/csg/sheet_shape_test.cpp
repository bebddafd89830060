// Sheets, f = phi(|g|) (csg/sheet_shape.hpp, api/sheet_meshing.hpp): the formula's split into its two
// walls, only where f = 0 stays off g = 0 in the box; and a sheet meshed as its walls: every vertex on
// f = 0, outward, free of self-intersections, the two walls' meshes exactly, the same bytes for any thread
// count, and a capped sheet thinner than an edge closed along its creases.
#include <gtest/gtest.h>

#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "csg/sheet_shape.hpp"
#include "mesh_checks.hpp"
#include "part_checks.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

const std::string kSheetGyroid = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)";

Box sheet_cube(double a) {
  return {Vec3::Constant(-a), Vec3::Constant(a)};
}

std::optional<SheetShape> split_sheet(const std::string& formula, double a = 4.0) {
  return split_sheet_shape(*expression_surface(formula, sheet_cube(a)), sheet_cube(a));
}

double sheet_gyroid(const Vec3& p) {
  return std::sin(p.x()) * std::cos(p.y()) + std::sin(p.y()) * std::cos(p.z()) +
         std::sin(p.z()) * std::cos(p.x());
}

TEST(SheetShape, AnAbsBehindStepsIsTwoWalls) {
  const Vec3 p(0.3, -0.7, 1.1);
  const auto sheet = split_sheet("2*(abs(" + kSheetGyroid + ")-0.3)");
  ASSERT_TRUE(sheet);
  EXPECT_NEAR(sheet->walls[0]->value(p), 2.0 * (sheet_gyroid(p) - 0.3), 1e-14);
  EXPECT_NEAR(sheet->walls[1]->value(p), 2.0 * (-sheet_gyroid(p) - 0.3), 1e-14);
  // Order reversed: the solid outside the sheet, each wall's gradient still out of the solid.
  const auto outside = split_sheet("0.3-abs(" + kSheetGyroid + ")");
  ASSERT_TRUE(outside);
  EXPECT_NEAR(outside->walls[0]->value(p), 0.3 - sheet_gyroid(p), 1e-14);
  EXPECT_NEAR(outside->walls[1]->value(p), 0.3 + sheet_gyroid(p), 1e-14);
  // A thickness that varies, positive throughout the box; a term free of the abs on either side.
  ASSERT_TRUE(split_sheet("abs(" + kSheetGyroid + ")-(0.2+0.04*x)"));
  ASSERT_TRUE(split_sheet("-(0.2+0.04*x)+abs(" + kSheetGyroid + ")"));
}

TEST(SheetShape, WallsThatMeetOrAnAbsNotUnderStepsAreNoSheet) {
  EXPECT_FALSE(split_sheet(kSheetGyroid));                              // no abs
  EXPECT_FALSE(split_sheet("abs(" + kSheetGyroid + ")+0.3"));           // f > 0 everywhere
  EXPECT_FALSE(split_sheet("abs(" + kSheetGyroid + ")-(0.2+0.1*x)"));   // thickness 0 at x = -2
  EXPECT_FALSE(split_sheet("abs(" + kSheetGyroid + ")*(x*x+1)-0.3"));   // a product with a variable
  EXPECT_FALSE(split_sheet("max(abs(" + kSheetGyroid + ")-0.3,x-1)"));  // a max at the root (a capped sheet)
  EXPECT_FALSE(split_sheet("abs(x)+abs(" + kSheetGyroid + ")-0.3"));    // two abs on the path
  // Within a box where the thickness stays positive, the same varying sheet is one.
  EXPECT_TRUE(split_sheet("abs(" + kSheetGyroid + ")-(0.2+0.1*x)", 1.9));
}

TEST(SheetMeshing, ASheetThinnerThanAnEdgeIsItsTwoWalls) {
  // Walls 2 t / |grad g| apart, down to 0.1 at t = 0.12, under the edge 0.15.
  const std::string formula = "abs(" + kSheetGyroid + ")-0.12";
  const SurfacePtr f = expression_surface(formula, sheet_cube(3.2));
  Settings s;
  s.box = sheet_cube(3.0);
  s.edge_length = 0.15;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*f, s, &stats);
  ASSERT_TRUE(stats.sheet);
  EXPECT_EQ(stats.sheet->walls, 2u);
  EXPECT_EQ(stats.vertices, mesh.vertex_count());
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_EQ(test::count_self_intersections(mesh, 10), 0u);
  EXPECT_LT(test::max_vertex_distance(*f, mesh), 1e-9);
  // Outward: each triangle's normal along grad f at its centroid.
  for (const Triangle& tri : mesh.triangles) {
    const Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]], c = mesh.positions[tri[2]];
    ASSERT_GT((b - a).cross(c - a).dot(f->value_gradient((a + b + c) / 3.0).gradient), 0.0);
  }
  // Exactly the two walls' meshes, one after the other.
  const auto sheet = split_sheet_shape(*f, sheet_cube(3.0));
  ASSERT_TRUE(sheet);
  const Mesh first = mesh_surface(*sheet->walls[0], s);
  const Mesh second = mesh_surface(*sheet->walls[1], s);
  ASSERT_EQ(mesh.vertex_count(), first.vertex_count() + second.vertex_count());
  EXPECT_EQ(mesh.positions[0], first.positions[0]);
  EXPECT_EQ(mesh.positions[first.vertex_count()], second.positions[0]);
  EXPECT_EQ(mesh.triangles.back()[0], second.triangles.back()[0] + first.vertex_count());
  // The same bytes for any thread count.
  Settings one = s;
  one.threads = 1;
  const Mesh single = mesh_surface(*f, one);
  EXPECT_EQ(single.positions, mesh.positions);
  EXPECT_EQ(single.triangles, mesh.triangles);
}

TEST(SheetMeshing, OneWallOutsideTheBoxLeavesTheOther) {
  // g = z: the wall z = -0.3 lies below the box.
  const SurfacePtr f = expression_surface("abs(z+sin(x)*0.1)-0.3", sheet_cube(1.0));
  Settings s;
  s.box = Box{Vec3(-1, -1, -0.1), Vec3(1, 1, 1)};
  s.edge_length = 0.2;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*f, s, &stats);
  ASSERT_TRUE(stats.sheet);
  EXPECT_EQ(stats.sheet->walls, 1u);
  for (const Vec3& p : mesh.positions) EXPECT_NEAR(p.z() + std::sin(p.x()) * 0.1, 0.3, 1e-9);
  // Neither wall in the box: refused as any surface that does not cross it.
  s.box = Box{Vec3(-1, -1, -0.2), Vec3(1, 1, 0.2)};
  EXPECT_THROW(mesh_surface(*f, s), NoSurfaceError);
}

TEST(SheetMeshing, ACappedSheetThinnerThanAnEdgeIsClosedAlongItsCreases) {
  const std::string formula = "max(abs(" + kSheetGyroid + ")-0.12,max(max(abs(x),abs(y)),abs(z))-pi)";
  test::CappedRun run{expression_surface(formula, sheet_cube(3.4)), {}, {}};
  Settings s;
  s.edge_length = 0.15;
  run.mesh = mesh_surface(*run.surface, s, &run.stats);
  ASSERT_TRUE(run.stats.sheet);
  EXPECT_EQ(run.stats.sheet->walls, 2u);
  const std::vector<SurfacePtr> faces = {expression_surface(kSheetGyroid + "-0.12", sheet_cube(3.4)),
                                         expression_surface("-(" + kSheetGyroid + ")-0.12", sheet_cube(3.4)),
                                         expression_surface("x-pi", sheet_cube(3.4)),
                                         expression_surface("-x-pi", sheet_cube(3.4)),
                                         expression_surface("y-pi", sheet_cube(3.4)),
                                         expression_surface("-y-pi", sheet_cube(3.4)),
                                         expression_surface("z-pi", sheet_cube(3.4)),
                                         expression_surface("-z-pi", sheet_cube(3.4))};
  // The gyroid passes through the box's corners and the middles of its edges, so the sheet crosses every
  // edge of the box there: the caps are strips about 2 t / |grad g| = 0.2 wide that end at the edge, under
  // two edges, whose triangles keep 17 to 25 degrees (docs/lattices.md, "Limits"); within two edges of the
  // box's edges the floor is not asked, everywhere else it holds.
  const auto near_corner = [](const Vec3& p) {
    const Vec3 off = (p.cwiseAbs() - Vec3::Constant(std::numbers::pi)).cwiseAbs();
    int near = 0;
    for (int k = 0; k < 3; ++k) near += off[k] < 2.0 * 0.15 ? 1 : 0;
    return near >= 2;
  };
  test::expect_valid_part(run, faces, sheet_cube(3.4).diagonal(), true, near_corner);
}

}  // namespace
}  // namespace isopatch
