// Formulas with creases meshed along them through mesh_surface() (api/crease_meshing.hpp): the cube
// end to end, the switch between automatic and smooth treatment, and the errors of bad shapes.
#include <gtest/gtest.h>

#include <isopatch/error.hpp>
#include <isopatch/topology.hpp>

#include "csg_checks.hpp"
#include "mesh_checks.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

using test::mesh_csg;

constexpr const char* kCube = "max(max(abs(x),abs(y)),abs(z))-1";
const Box kCubeBox{Vec3::Constant(-1.5), Vec3::Constant(1.5)};

TEST(CreaseMeshing, ACubeHasExactEdgesAndCornersAndGoodTriangles) {
  const test::CsgRun run = mesh_csg(kCube, kCubeBox);
  ASSERT_TRUE(run.stats.creases);
  EXPECT_EQ(run.stats.creases->faces, 6u);
  EXPECT_EQ(run.stats.creases->creases, 12u);
  EXPECT_EQ(run.stats.creases->corners, 8u);
  EXPECT_EQ(run.stats.creases->pieces, 6u);
  const TopologyReport topology = analyze_topology(run.mesh);
  EXPECT_TRUE(topology.watertight());
  EXPECT_TRUE(topology.manifold());
  EXPECT_TRUE(topology.consistently_oriented());
  EXPECT_EQ(topology.euler_characteristic, 2);
  EXPECT_EQ(topology.components.size(), 1u);
  // Every corner is a vertex; every vertex lies on the cube, those near an edge on both of its faces.
  for (const Vec3& corner : {Vec3(1, 1, 1), Vec3(-1, 1, 1), Vec3(1, -1, -1), Vec3(-1, -1, -1)}) {
    double nearest = 1.0;
    for (const Vec3& p : run.mesh.positions) nearest = std::min(nearest, (p - corner).norm());
    EXPECT_LT(nearest, 1e-12);
  }
  const auto [residual, crease_vertices] = test::crease_residual(run);
  EXPECT_GT(crease_vertices, 12u * 20u);
  EXPECT_LT(residual, 1e-9 * kCubeBox.diagonal());
  EXPECT_LT(test::max_vertex_distance(*run.surface, run.mesh), 1e-12);
  // Flat faces: the volume is exact to rounding; the angles reach the floor.
  EXPECT_NEAR(test::enclosed_volume(run.mesh), 8.0, 1e-9);
  EXPECT_GE(test::min_angle_degrees(run.mesh), 25.0);
  EXPECT_EQ(run.stats.warnings.exempt_corners, 0u);
}

TEST(CreaseMeshing, TheSameBytesForAnyNumberOfThreads) {
  const char* formula = "max(x^2+y^2+z^2-1,0.25-x^2-y^2)";
  const Box box{Vec3::Constant(-1.2), Vec3::Constant(1.2)};
  Settings s;
  s.threads = 1;
  const Mesh one = mesh_csg(formula, box, s).mesh;
  for (const int threads : {2, 4}) {
    s.threads = threads;
    const Mesh many = mesh_csg(formula, box, s).mesh;
    EXPECT_EQ(many.positions, one.positions) << threads;
    EXPECT_EQ(many.triangles, one.triangles) << threads;
  }
}

TEST(CreaseMeshing, CreasesOffMeshesAsBefore) {
  Settings off;
  off.creases = Creases::Off;
  const test::CsgRun smooth = mesh_csg(kCube, kCubeBox, off);
  EXPECT_FALSE(smooth.stats.creases);
  // The smooth treatment rounds the corners off: no vertex at a corner.
  double nearest = 1.0;
  for (const Vec3& p : smooth.mesh.positions) nearest = std::min(nearest, (p - Vec3(1, 1, 1)).norm());
  EXPECT_GT(nearest, 1e-6);
}

TEST(CreaseMeshing, ASmoothUnionWithoutCreasesKeepsItsSmoothMesh) {
  // Two spheres joined by a polynomial smooth minimum: switches, but no crease anywhere.
  const char* formula =
      "k=0.3;a=(x-0.5)^2+y^2+z^2-0.36;b=(x+0.5)^2+y^2+z^2-0.36;h=max(k-abs(a-b),0)/k;min(a,b)-h*h*k/4";
  const Box box{Vec3(-1.3, -0.9, -0.9), Vec3(1.3, 0.9, 0.9)};
  Settings off;
  off.creases = Creases::Off;
  const test::CsgRun automatic = mesh_csg(formula, box);
  const test::CsgRun smooth = mesh_csg(formula, box, off);
  EXPECT_FALSE(automatic.stats.creases);
  EXPECT_EQ(automatic.mesh.positions, smooth.mesh.positions);
  EXPECT_EQ(automatic.mesh.triangles, smooth.mesh.triangles);
}

TEST(CreaseMeshing, CreasesThePathsCannotFollowAreRoundedOrRefusedWhenExact) {
  // A pin of radius 0.02 on a cube, at the default edge (0.047): the general path cannot cut the pin's
  // face into pieces. By default the shape is meshed as a smooth surface, closed, with the reason in its
  // warnings; Creases::Exact refuses it with that reason and what would mesh it. Neither is a shape fault.
  const std::string pin = "min(" + std::string(kCube) + ",max(x^2+y^2-0.0004,abs(z-1.05)-0.05))";
  const Box box{Vec3::Constant(-1.5), Vec3::Constant(1.5)};
  test::CsgRun rounded;
  rounded.surface = expression_surface(pin, box);
  Settings automatic;
  automatic.box = box;
  rounded.mesh = mesh_surface(*rounded.surface, automatic, &rounded.stats);
  EXPECT_FALSE(rounded.stats.creases);
  EXPECT_EQ(rounded.stats.warnings.creases_rounded, 1u);
  EXPECT_NE(rounded.stats.warnings.crease_failure.find("near ("), std::string::npos);
  EXPECT_TRUE(analyze_topology(rounded.mesh).watertight());
  Settings exact;
  exact.creases = Creases::Exact;
  try {
    mesh_csg(pin, box, exact);
    ADD_FAILURE() << "no CreaseError with Creases::Exact";
  } catch (const ShapeNotManifoldError& e) {
    ADD_FAILURE() << "a pin is no shape fault: " << e.what();
  } catch (const CreaseError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(rounded.stats.warnings.crease_failure, 0), 0u) << what;
    EXPECT_NE(what.find("--edge-length 0.0234"), std::string::npos) << what;
    EXPECT_NE(what.find("--creases off"), std::string::npos) << what;
  }
}

TEST(CreaseMeshing, ACappedOperandWhoseCreasesLeaveTheBoxIsNeverRoundedSilently) {
  // A gyroid united with a rod, capped by a tilted plane: the capped operand min(g, rod) has a crease
  // that leaves the box. It used to be capped as if smooth (its crease rounded without a word, its mesh
  // crossing itself); now it goes to the crease paths, which say why they round it, and Creases::Exact
  // refuses it.
  const std::string part = "max(min(sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x),x^2+y^2-4),0.6*x+0.8*z-4)";
  const Box box{Vec3::Constant(-5.0), Vec3::Constant(5.0)};
  const SurfacePtr f = expression_surface(part, box);
  Settings automatic;
  automatic.box = box;
  automatic.edge_length = 0.25;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*f, automatic, &stats);
  EXPECT_FALSE(stats.creases);
  EXPECT_EQ(stats.warnings.creases_leave_box, 1u);
  EXPECT_TRUE(analyze_topology(mesh).manifold());
  EXPECT_EQ(test::count_self_intersections(mesh, 10), 0u);
  Settings exact = automatic;
  exact.creases = Creases::Exact;
  try {
    mesh_surface(*f, exact);
    ADD_FAILURE() << "no CreaseError with Creases::Exact";
  } catch (const CreaseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("leave the box"), std::string::npos) << what;
    EXPECT_NE(what.find("--creases off"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(CreaseMeshing, BadShapesGetClearErrors) {
  // Two boxes touching along an edge: not a 2-manifold, refused whatever Settings::creases asks.
  EXPECT_THROW(mesh_csg("min(max(max(abs(x),abs(y)),abs(z))-1,max(max(abs(x-2),abs(y-2)),abs(z))-1)",
                        Box{Vec3(-1.5, -1.5, -1.5), Vec3(3.5, 3.5, 1.5)}),
               CreaseError);
  // A sphere resting on a box: the faces touch at a point.
  EXPECT_THROW(mesh_csg("min(max(max(abs(x),abs(y)),abs(z))-1,x^2+y^2+(z-1.5)^2-0.25)",
                        Box{Vec3(-1.5, -1.5, -1.5), Vec3(1.5, 1.5, 2.2)}),
               CreaseError);
  // Creases that leave the box: a polyhedron is cut open by the box along its creases (its caps, open
  // on the box's face: docs/lattices.md), nothing to warn about.
  const test::CsgRun open = mesh_csg(kCube, Box{Vec3(-1.5, -1.5, -1.5), Vec3(1.5, 1.5, 0.5)});
  ASSERT_TRUE(open.stats.creases);
  EXPECT_EQ(open.stats.creases->caps, 5u);
  EXPECT_EQ(open.stats.warnings.creases_leave_box, 0u);
  EXPECT_GT(open.mesh.triangle_count(), 100u);
  for (std::uint32_t v : test::boundary_vertices(open.mesh)) EXPECT_EQ(open.mesh.positions[v].z(), 0.5);
  // A formula whose creases leave the box and that is no capped solid: cut open by the box along its
  // creases (the shape intersected with the box's planes, their caps taken away), nothing to warn about.
  // (A ball on the cube's face x = 1, through the box's top: its crease with the cube reaches the top.)
  const test::CsgRun cut = mesh_csg("min(" + std::string(kCube) + ",(x-1)^2+y^2+(z-0.2)^2-0.2025)",
                                    Box{Vec3(-1.5, -1.5, -1.5), Vec3(1.5, 1.5, 0.5)});
  ASSERT_TRUE(cut.stats.creases);
  EXPECT_EQ(cut.stats.creases->cut_planes, 6u);
  EXPECT_EQ(cut.stats.warnings.creases_leave_box, 0u);
  for (std::uint32_t v : test::boundary_vertices(cut.mesh)) EXPECT_EQ(cut.mesh.positions[v].z(), 0.5);
  EXPECT_GE(test::min_angle_degrees(cut.mesh), 25.0);
  // Two tori whose intersection is empty at this edge length (found by the random models of issue 56):
  // no surface, as for a box f = 0 does not cross, not an empty mesh.
  EXPECT_THROW(mesh_csg("max((sqrt((x+0.529)^2+(y-0.07)^2)-0.518)^2+(z+0.413)^2-0.099225,"
                        "((sqrt((x+0.213)^2+(y-0.456)^2)-0.669)^2+(z-0.329)^2-0.051984)+0.006)",
                        Box{Vec3(-1.588, -1.68, -1.569), Vec3(1.662, 1.687, 1.675)},
                        [] {
                          Settings s;
                          s.edge_length = 0.2;
                          s.quality = Quality::Preview;
                          return s;
                        }()),
               NoSurfaceError);
}

}  // namespace
}  // namespace isopatch
