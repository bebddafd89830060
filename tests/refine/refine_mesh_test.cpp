// The refinement stage on its own: a base mesh cut k times, on f = 0, watertight, regular, the same
// bytes for any thread count; the guard against another sheet; cut boundaries on their planes.
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cmath>

#include "mesh_checks.hpp"
#include "refine/refine_mesh.hpp"
#include "test_surfaces.hpp"

namespace isopatch::refine {
namespace {

/// A coarse base of `s` from today's pipeline (no refinement).
Mesh base_of(const Surface& s, double edge, std::optional<Box> box = std::nullopt) {
  Settings settings;
  settings.refine = 1;
  settings.edge_length = edge;
  settings.box = box;
  return mesh_surface(s, settings);
}

TEST(RefineMesh, SphereRefinedIsWatertightRegularAndOnTheSurface) {
  const SurfacePtr s = test::sphere();
  const Mesh base = base_of(*s, 0.3);
  RefineParams p;
  p.level = 5;
  const RefineResult r = refine_mesh(base, *s, p);
  ASSERT_EQ(r.failed_points, 0u);
  const Mesh& mesh = r.mesh;
  EXPECT_EQ(mesh.triangle_count(), base.triangle_count() * 25);
  EXPECT_EQ(mesh.vertex_count(),
            base.vertex_count() + (base.triangle_count() * 3 / 2) * 4 + base.triangle_count() * 6);
  const QualityReport q = analyze_quality(mesh, s.get());
  EXPECT_TRUE(q.topology.watertight());
  EXPECT_TRUE(q.topology.manifold());
  EXPECT_TRUE(q.topology.outward_oriented());
  EXPECT_EQ(q.topology.genus, 0);
  EXPECT_LT(test::max_vertex_distance(*s, mesh), 1e-10);
  // Only the base's own irregular vertices stay irregular: at most 1/25 of the output's vertices.
  const QualityReport qb = analyze_quality(base, s.get());
  EXPECT_GE(q.valence.share_6, 1.0 - (1.0 - qb.valence.share_6) / 20.0);
  EXPECT_GE(q.shape.min_angle.min, 25.0);
  EXPECT_NEAR(r.smallest_angle, q.shape.min_angle.min, 1e-6);
  EXPECT_GT(r.gradient_evaluations, 0u);
}

TEST(RefineMesh, SameBytesForAnyThreadCount) {
  const SurfacePtr s = test::torus();
  const Mesh base = base_of(*s, 0.25);
  RefineParams p;
  p.level = 6;
  p.sweep_block = 1000;  // several blocks per sweep, as on meshes of millions of vertices
  std::vector<Mesh> meshes;
  for (int threads : {1, 2, 4}) {
    tbb::task_arena arena(threads);
    meshes.push_back(arena.execute([&] { return refine_mesh(base, *s, p).mesh; }));
  }
  ASSERT_FALSE(meshes[0].triangles.empty());
  for (std::size_t i = 1; i < meshes.size(); ++i) {
    EXPECT_EQ(meshes[i].triangles, meshes[0].triangles);
    ASSERT_EQ(meshes[i].positions.size(), meshes[0].positions.size());
    for (std::size_t v = 0; v < meshes[0].positions.size(); ++v)
      ASSERT_EQ(meshes[i].positions[v], meshes[0].positions[v]) << "vertex " << v;
  }
}

TEST(RefineMesh, APointThatLandsOnAnotherSheetFailsTheGuard) {
  // An octahedron on the unit sphere, refined against f whose zero set is that sphere and one of radius
  // 0.9 inside it: the face centres (at 0.58 from the centre) land on the inner sheet, whose normal
  // points inwards.
  Mesh base;
  base.positions = {Vec3(1, 0, 0),  Vec3(-1, 0, 0), Vec3(0, 1, 0),
                    Vec3(0, -1, 0), Vec3(0, 0, 1),  Vec3(0, 0, -1)};
  base.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  const SurfacePtr two = make_surface(
      [](auto x, auto y, auto z) {
        auto r2 = x * x + y * y + z * z;
        return (r2 - 1.0) * (r2 - 0.81);
      },
      Box{Vec3::Constant(-1.2), Vec3::Constant(1.2)}, "two spheres");
  RefineParams p;
  p.level = 6;
  const RefineResult r = refine_mesh(base, *two, p);
  EXPECT_GT(r.failed_points, 0u);
  EXPECT_TRUE(r.mesh.triangles.empty());
  // The same base against the sphere alone refines (the guard is not what fails it).
  const RefineResult one = refine_mesh(base, *test::sphere(), p);
  EXPECT_EQ(one.failed_points, 0u);
}

TEST(RefineMesh, ACutBoundaryStaysOnItsBoxFaceAndOnTheSurface) {
  const SurfacePtr s = test::sphere();
  const Box box{Vec3::Constant(-1.2), Vec3(1.2, 1.2, 0.5)};
  const Mesh base = base_of(*s, 0.25, box);
  RefineParams p;
  p.level = 4;
  p.box = box;
  const RefineResult r = refine_mesh(base, *s, p);
  ASSERT_EQ(r.failed_points, 0u);
  const std::set<std::uint32_t> boundary = test::boundary_vertices(r.mesh);
  ASSERT_GT(boundary.size(), base.vertex_count() / 10);
  for (const std::uint32_t v : boundary) {
    EXPECT_EQ(r.mesh.positions[v].z(), 0.5) << "vertex " << v;
    EXPECT_LT(std::abs(r.mesh.positions[v].squaredNorm() - 1.0), 1e-10) << "vertex " << v;
  }
  const TopologyReport t = analyze_topology(r.mesh);
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_GE(test::min_angle_degrees(r.mesh), 20.0);
}

TEST(RefineMesh, RefusesAnOutputBeyondTheVertexBudgetAndStopsWhenCancelled) {
  const SurfacePtr s = test::sphere();
  const Mesh base = base_of(*s, 0.3);
  RefineParams p;
  p.level = 8;
  p.max_vertices = 1000;
  try {
    refine_mesh(base, *s, p);
    FAIL() << "no LimitError";
  } catch (const LimitError& e) {
    EXPECT_EQ(e.setting(), "max_vertices");
    EXPECT_NE(std::string(e.what()).find("vertices"), std::string::npos);
  }
  p.max_vertices = 0;
  const std::atomic<bool> cancel{true};
  p.cancel = &cancel;
  EXPECT_THROW(refine_mesh(base, *s, p), LimitError);
}

}  // namespace
}  // namespace isopatch::refine
