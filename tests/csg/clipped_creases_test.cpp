// CSG shapes cut open along their creases (api/clipped_creases.hpp): by a region's plane and by the box
// where the shape's creases leave it. Open meshes whose boundary lies exactly on the cutting planes, every
// vertex on f = 0, every vertex where two faces meet on both, the angle floor, manifold and outward; a
// smooth formula in a region keeps its smooth mesh; a shape whose cut cannot be meshed along its creases
// is meshed smooth with the warning.
#include <gtest/gtest.h>

#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "mesh_checks.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

struct CutRun {
  SurfacePtr f;
  Mesh mesh;
  MeshStats stats;
};

CutRun mesh_cut(const std::string& formula, const Box& box, const ConvexRegion& region) {
  CutRun run{expression_surface(formula, box), {}, {}};
  Settings s;
  s.box = box;
  s.region = region;
  run.mesh = mesh_surface(*run.f, s, &run.stats);
  return run;
}

/// Open, manifold, outward, free of self-intersections, on f = 0, over the angle floor; every vertex on
/// two of `faces` (a crease) on both to 1e-9 of the diagonal; returns the crease vertices.
std::size_t expect_open_part(const CutRun& run, const std::vector<SurfacePtr>& faces, const Box& box) {
  const double diagonal = box.diagonal();
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_GT(t.boundary_edges, 0u);
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_EQ(t.unreferenced_vertices, 0u);
  EXPECT_EQ(test::count_self_intersections(run.mesh, 10), 0u);
  EXPECT_LT(test::max_vertex_distance(*run.f, run.mesh), 1e-9 * diagonal);
  EXPECT_GE(test::min_angle_degrees(run.mesh), 25.0);
  for (const Triangle& tri : run.mesh.triangles) {
    const Vec3 a = run.mesh.positions[tri[0]], b = run.mesh.positions[tri[1]], c = run.mesh.positions[tri[2]];
    const Vec3 centre = (a + b + c) / 3.0;
    EXPECT_GT((b - a).cross(c - a).dot(run.f->value_gradient(centre).gradient), 0.0);
  }
  std::size_t creases = 0;
  for (const Vec3& p : run.mesh.positions) {
    int on = 0;
    for (const SurfacePtr& face : faces) {
      const ValueGradient g = face->value_gradient(p);
      if (std::abs(g.value) / g.gradient.norm() < 1e-9 * diagonal) ++on;
    }
    if (on >= 2) ++creases;
  }
  return creases;
}

TEST(ClippedCreases, ADrilledSphereCutByARegionKeepsItsCreasesAndItsCut) {
  const Box box{Vec3::Constant(-1.2), Vec3::Constant(1.2)};
  const CutRun run = mesh_cut("max(x^2+y^2+z^2-1,0.25-x^2-y^2)", box, {{1.0, 0.0, 0.0, -0.3}});
  ASSERT_TRUE(run.stats.creases);
  EXPECT_EQ(run.stats.creases->cut_planes, 1u);
  EXPECT_EQ(run.stats.warnings.creases_in_partition, 0u);
  // The hole's two rims are creases; the cut at x = 0.3 is exact.
  const std::vector<SurfacePtr> faces = {expression_surface("x^2+y^2+z^2-1", box),
                                         expression_surface("0.25-x^2-y^2", box)};
  EXPECT_GT(expect_open_part(run, faces, box), 40u);
  for (std::uint32_t v : test::boundary_vertices(run.mesh)) EXPECT_EQ(run.mesh.positions[v].x(), 0.3);
  for (const Vec3& p : run.mesh.positions) EXPECT_LE(p.x(), 0.3);
}

TEST(ClippedCreases, CreasesThatLeaveTheBoxAreCutByIt) {
  // A square bar along z joined by a round rod along y (a union: no capped solid): the bar's four edges
  // leave the box at z = +-1, the rod at y = +-1.5.
  const Box box{Vec3(-1.5, -1.5, -1.0), Vec3(1.5, 1.5, 1.0)};
  const CutRun run = mesh_cut("min(max(abs(x),abs(y))-0.6,x^2+z^2-0.16)", box, {});
  ASSERT_TRUE(run.stats.creases);
  EXPECT_EQ(run.stats.creases->cut_planes, 6u);
  EXPECT_EQ(run.stats.warnings.creases_leave_box, 0u);
  const std::vector<SurfacePtr> faces = {expression_surface("x-0.6", box), expression_surface("-x-0.6", box),
                                         expression_surface("y-0.6", box), expression_surface("-y-0.6", box),
                                         expression_surface("x^2+z^2-0.16", box)};
  EXPECT_GT(expect_open_part(run, faces, box), 4u * 10u);
  for (std::uint32_t v : test::boundary_vertices(run.mesh)) {
    const Vec3& p = run.mesh.positions[v];
    EXPECT_TRUE(std::abs(p.z()) == 1.0 || std::abs(p.y()) == 1.5) << p.transpose();
  }
}

TEST(ClippedCreases, SmoothFormulasInARegionKeepTheirSmoothMesh) {
  const Box box{Vec3::Constant(-1.5), Vec3::Constant(1.5)};
  const CutRun run = mesh_cut("x^2+y^2+z^2-1", box, {{1.0, 0.0, 0.0, -0.3}});
  EXPECT_FALSE(run.stats.creases);
  EXPECT_EQ(run.stats.warnings.creases_in_partition, 0u);
}

TEST(ClippedCreases, TwoSolidsCutByTheBoxAreMeshedAlongTheirCreaseUpToTheBox) {
  // A ball minus an ellipsoid that the box cuts (random model 270 of docs/robustness.md): the general path
  // closes pieces by fans whose triangles cross, and the smooth mesh rounds the crease. As two smooth
  // solids intersected (api/curved_cut.hpp), the crease runs in an arc from the box to the box: the part
  // is open exactly on the box, free of crossings, with the crease on both faces.
  const Box box{Vec3(-1.031, -0.977, -0.964), Vec3(0.994, 1.015, 0.904)};
  const std::string ball = "(x-(0.277))^2+(y-(0.339))^2+(z-(-0.577))^2-0.913936";
  const std::string ellipsoid = "-(((x-(-0.549))/0.587)^2+((y-(0.376))/0.997)^2+((z-(0.055))/0.848)^2-1)";
  const SurfacePtr f = expression_surface("max(" + ball + "," + ellipsoid + ")", box);
  Settings s;
  s.box = box;
  s.edge_length = 0.0625;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*f, s, &stats);
  ASSERT_TRUE(stats.creases);
  EXPECT_EQ(stats.creases->faces, 2u);
  EXPECT_EQ(stats.warnings.creases_leave_box, 0u);
  EXPECT_EQ(stats.warnings.fan_patches, 0u);
  EXPECT_EQ(test::count_self_intersections(mesh, 10), 0u);
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_GT(t.boundary_edges, 0u);
  const SurfacePtr a = expression_surface(ball, box), b = expression_surface(ellipsoid, box);
  std::size_t crease = 0;
  for (const Vec3& p : mesh.positions) {
    const double da = std::abs(a->value(p)) / a->value_gradient(p).gradient.norm();
    const double db = std::abs(b->value(p)) / b->value_gradient(p).gradient.norm();
    EXPECT_LT(std::min(da, db), 1e-9 * box.diagonal());
    crease += da < 1e-9 * box.diagonal() && db < 1e-9 * box.diagonal() ? 1 : 0;
  }
  EXPECT_GT(crease, 20u);
  EXPECT_GE(test::min_angle_degrees(mesh), 25.0);
}

TEST(ClippedCreases, AShapeThatCannotBeCutAlongItsCreasesIsSaid) {
  // Two boxes touching along an edge are no 2-manifold: cut by a region, meshed smooth, with the warning.
  const Box box{Vec3(-1.5, -1.5, -1.5), Vec3(3.5, 3.5, 1.5)};
  const CutRun run = mesh_cut("min(max(max(abs(x),abs(y)),abs(z))-1,max(max(abs(x-2),abs(y-2)),abs(z))-1)",
                              box, {{0.0, 0.0, 1.0, -0.5}});
  EXPECT_FALSE(run.stats.creases);
  EXPECT_EQ(run.stats.warnings.creases_in_partition, 1u);
  EXPECT_GT(run.mesh.triangle_count(), 100u);
}

}  // namespace
}  // namespace isopatch
