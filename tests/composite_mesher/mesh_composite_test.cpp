// The public call mesh_composite(): projection and Marching Cubes on the same composite, budgets.
#include <isopatch/composite_mesh.hpp>
#include <isopatch/error.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include "test_composites.hpp"

namespace isopatch {
namespace {

TEST(MeshComposite, ProjectionAndMarchingCubesBothCloseTheSphere) {
  const CompositeModel model(test::cube_sphere());
  EXPECT_EQ(model.patch_count(), 6u);
  Settings s;
  s.edge_length = 0.15;
  MeshStats stats;
  const Mesh projected = mesh_composite(model, s, &stats);
  ASSERT_TRUE(stats.projection);
  EXPECT_EQ(stats.projection->patches_by_sides.at(4), 6u);
  EXPECT_EQ(stats.projection->fallback_cells, 0u);
  EXPECT_EQ(stats.vertices, projected.vertex_count());
  s.method = Method::MarchingCubes;
  s.grid = 40;
  MeshStats mc_stats;
  const Mesh mc = mesh_composite(model, s, &mc_stats);
  EXPECT_TRUE(mc_stats.marching_cubes);
  for (const Mesh* m : {&projected, &mc}) {
    const TopologyReport t = analyze_topology(*m);
    EXPECT_TRUE(t.watertight());
    EXPECT_TRUE(t.consistently_oriented());
    EXPECT_EQ(t.genus, 0);
    for (const Vec3& p : m->positions) EXPECT_NEAR(p.norm(), std::sqrt(3.0), 1e-9);
  }
  // Projection's triangles are far better shaped than Marching Cubes' on the same surface.
  EXPECT_GT(analyze_shape(projected).min_angle.min, 20.0);
  EXPECT_LT(analyze_shape(mc).min_angle.min, 10.0);
}

TEST(MeshComposite, BudgetsStopTheProjection) {
  const CompositeModel model(test::octahedron_sphere());
  Settings s;
  s.edge_length = 0.05;
  s.max_evaluations = 1000;
  try {
    mesh_composite(model, s);
    FAIL() << "no LimitError";
  } catch (const LimitError& e) {
    EXPECT_EQ(e.setting(), "max_evaluations");
  }
  s.max_evaluations = 0;
  s.edge_length = 0.0;
  EXPECT_THROW(mesh_composite(model, s), SettingError);
}

TEST(MeshComposite, CompositePaths) {
  EXPECT_TRUE(is_composite_path("a/b.ipatch"));
  EXPECT_FALSE(is_composite_path(".ipatch"));
  EXPECT_FALSE(is_composite_path("sphere"));
  EXPECT_FALSE(is_composite_path("x.ipatch.ply"));
}

}  // namespace
}  // namespace isopatch
