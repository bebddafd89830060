// The composite mesher on composites whose surface is known exactly (test_composites.hpp): the
// octahedron's 8 octants of the unit sphere and the cube's 6 patches of the sphere of radius sqrt(3).
#include <isopatch/error.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>

#include "analysis/composite_quality.hpp"
#include "composite_mesher/composite_mesher.hpp"
#include "self_intersection.hpp"
#include "test_composites.hpp"

namespace isopatch {
namespace {

struct Case {
  const char* name;
  std::shared_ptr<Composite> (*make)();
  double radius;
};

class SphereComposites : public ::testing::TestWithParam<Case> {};

void expect_closed_sphere(const Composite& c, const CompositeMesh& m, double radius) {
  const TopologyReport t = analyze_topology(m.mesh);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_TRUE(t.outward_oriented());
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.genus, 0);
  EXPECT_EQ(t.duplicate_vertices, 0u);
  EXPECT_EQ(test::count_self_intersections(m.mesh), 0u);
  for (const Vec3& p : m.mesh.positions) EXPECT_NEAR(p.norm(), radius, 1e-9 * radius);
  const CompositeQuality q = measure_composite_mesh(c, m);
  EXPECT_LE(q.max_relative_distance, 1e-9);
}

TEST_P(SphereComposites, MeshesWatertightOnTheSphereWithGoodTrianglesInsidePatches) {
  const auto c = GetParam().make();
  Settings s;
  s.edge_length = 0.08 * GetParam().radius;
  const CompositeMesh m = mesh_composite_projection(*c, s);
  expect_closed_sphere(*c, m, GetParam().radius);
  const CompositeQuality q = measure_composite_mesh(*c, m);
  std::printf(
      "%s: %zu vertices, patch valence 6 %.3f, patch min angle %.1f, min angle %.1f, distance %.2g, "
      "normal jump seam %.3f patch %.3f deg/unit (worst seam %.2f), seam gradient angle %.2g deg\n",
      GetParam().name, m.mesh.vertex_count(), q.patch_valence_6, q.patch_min_angle, q.min_angle,
      q.max_relative_distance, q.seam_normal_jump, q.patch_normal_jump, q.worst_seam_ratio,
      q.seam_gradient_angle);
  EXPECT_GE(q.patch_valence_6, 0.90);
  EXPECT_GE(q.patch_min_angle, 20.0);
  // The composite is exactly the sphere, so the normal turns across seams as it does inside patches.
  EXPECT_LT(q.seam_gradient_angle, 1e-5);
  EXPECT_GT(q.seam_edges, 0u);
  EXPECT_LT(q.seam_normal_jump, 2.0 * q.patch_normal_jump);
  EXPECT_LT(q.worst_seam_ratio, 1.5);
  EXPECT_GT(q.seam_normal_jump, 0.5 * q.patch_normal_jump);
}

TEST_P(SphereComposites, PapersMethodAloneIsWatertightAndOnTheSphere) {
  const auto c = GetParam().make();
  Settings s;
  s.edge_length = 0.1 * GetParam().radius;
  s.remesh_iterations = 0;
  const CompositeMesh m = mesh_composite_projection(*c, s);
  expect_closed_sphere(*c, m, GetParam().radius);
}

TEST_P(SphereComposites, CurvesAreSampledOnceAndSharedByBothPatches) {
  const auto c = GetParam().make();
  Settings s;
  s.resolution = 5;
  s.remesh_iterations = 0;
  const CompositeMesh m = mesh_composite_projection(*c, s);
  std::size_t corners = 0;
  for (const std::int32_t p : m.vertex_patch) corners += p < 0 ? 1 : 0;
  // V - E + F = 2 on the polyhedron: corners V, every curve's 4 inner samples once.
  std::size_t polyhedron_vertices = 0;
  {
    std::set<std::array<double, 3>> seen;
    for (const ConicArc& a : c->curves) {
      seen.insert({a.start.x(), a.start.y(), a.start.z()});
      seen.insert({a.end.x(), a.end.y(), a.end.z()});
    }
    polyhedron_vertices = seen.size();
  }
  EXPECT_EQ(corners, polyhedron_vertices + 4 * c->curves.size());
  for (const int k : m.curve_segments) EXPECT_EQ(k, 5);
}

TEST_P(SphereComposites, SameBytesForAnyThreadCount) {
  const auto c = GetParam().make();
  Settings s;
  s.edge_length = 0.15 * GetParam().radius;
  const auto run = [&](int threads) {
    tbb::task_arena arena(threads);
    return arena.execute([&] { return mesh_composite_projection(*c, s).mesh; });
  };
  const Mesh one = run(1);
  const Mesh four = run(4);
  ASSERT_EQ(one.positions.size(), four.positions.size());
  EXPECT_EQ(one.triangles, four.triangles);
  for (std::size_t i = 0; i < one.positions.size(); ++i) EXPECT_EQ(one.positions[i], four.positions[i]);
}

INSTANTIATE_TEST_SUITE_P(Composites, SphereComposites,
                         ::testing::Values(Case{"octahedron", &test::octahedron_sphere, 1.0},
                                           Case{"cube", &test::cube_sphere, std::sqrt(3.0)}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(CompositeMesher, SeamMeasureTellsACreaseFromASmoothSeam) {
  const auto c = test::creased_cube();
  Settings s;
  s.edge_length = 0.1;
  const CompositeMesh m = mesh_composite_projection(*c, s);
  const TopologyReport t = analyze_topology(m.mesh);
  EXPECT_TRUE(t.watertight());
  EXPECT_EQ(t.genus, 0);
  const CompositeQuality q = measure_composite_mesh(*c, m);
  EXPECT_LE(q.max_relative_distance, 1e-12);
  EXPECT_NEAR(q.patch_normal_jump, 0.0, 1e-6);  // flat faces
  EXPECT_GT(q.worst_seam_ratio, 100.0);         // 90 degrees over an edge, against 1 degree over the box
  EXPECT_GT(q.seam_gradient_angle, 89.0);
}

TEST(CompositeMesher, RefusesInconsistentTopology) {
  auto c = test::octahedron_sphere();
  c->patches[0].sides[0].reversed = !c->patches[0].sides[0].reversed;
  EXPECT_THROW(mesh_composite_projection(*c, Settings{}), InputError);
  c = test::octahedron_sphere();
  c->patches[1].sides.pop_back();
  c->patches[1].corner_directions.pop_back();
  EXPECT_THROW(mesh_composite_projection(*c, Settings{}), InputError);
  c = test::octahedron_sphere();
  c->patches[2].sides[1].curve = 999;
  EXPECT_THROW(mesh_composite_projection(*c, Settings{}), InputError);
  c = test::octahedron_sphere();
  c->patches[3].corner_directions[0] = Vec3(NAN, 0, 0);
  EXPECT_THROW(mesh_composite_projection(*c, Settings{}), InputError);
}

TEST(CompositeMesher, VertexRolesNameCornersCurvesAndInteriors) {
  const auto c = test::cube_sphere();
  Settings s;
  s.resolution = 4;
  s.remesh_iterations = 0;
  s.vertex_roles = true;
  const CompositeMesh m = mesh_composite_projection(*c, s);
  const std::vector<float>* roles = m.mesh.find_attribute("role");
  ASSERT_NE(roles, nullptr);
  std::map<float, std::size_t> count;
  for (const float r : *roles) ++count[r];
  EXPECT_EQ(count[0.0f], 8u);        // the cube's corners
  EXPECT_EQ(count[1.0f], 12u * 3u);  // 3 inner samples on each of 12 curves
  EXPECT_EQ(count[2.0f], 6u * 9u);   // a 5 x 5 grid's 9 inner vertices per face
}

TEST(CompositeMesher, OpenCompositeKeepsItsCurvesAsBoundary) {
  auto c = test::octahedron_sphere();
  c->patches.resize(1);  // the octant x, y, z >= 0 alone
  Settings s;
  s.edge_length = 0.1;
  const CompositeMesh m = mesh_composite_projection(*c, s);
  const TopologyReport t = analyze_topology(m.mesh);
  std::size_t curve_segments = 0;
  for (const PatchSide& side : c->patches[0].sides)
    curve_segments += static_cast<std::size_t>(m.curve_segments[side.curve]);
  EXPECT_EQ(t.boundary_edges, curve_segments);
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 1);  // a disc
  for (const Vec3& p : m.mesh.positions) {
    EXPECT_NEAR(p.norm(), 1.0, 1e-9);
    EXPECT_GE(p.minCoeff(), -1e-12);
  }
}

TEST(CompositeMesher, VertexBudget) {
  const auto c = test::octahedron_sphere();
  Settings s;
  s.edge_length = 0.02;
  s.max_vertices = 100;
  EXPECT_THROW(mesh_composite_projection(*c, s), LimitError);
}

}  // namespace
}  // namespace isopatch
