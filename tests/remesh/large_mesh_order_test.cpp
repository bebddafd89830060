// A mesh large enough that every clean-up round renumbers its vertices in space order
// (remesh_thresholds.hpp, kSpaceOrderSlots): the per-vertex data the rounds keep (sizes, sliding
// boundary vertices) follow the renumbering, so the result meets the quality floor (closed, genus 0, no
// self-intersections, vertices on f = 0, valence 6 >= 90%, smallest angle >= 20 degrees) and is the
// same bytes on 1 and 2 threads. The tanglecube in a box that cuts it also checks the vertices that
// slide along the box faces: every boundary vertex stays on a face. (Label "validation": a few seconds each,
// not run under the sanitizers.)
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>

#include "surface_mesh_expectations.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace {

Mesh mesh_with_threads(const Surface& s, Settings settings, int threads, MeshStats* stats = nullptr) {
  settings.threads = threads;
  return mesh_surface(s, settings, stats);
}

TEST(LargeMeshOrder, ClosedSurfaceMeetsTheFloorAndIsTheSameOnAnyThreadCount) {
  const SurfacePtr s = test::sphere(1.0);
  Settings settings;
  settings.edge_length = 0.0165;  // about 60k vertices: past the threshold from the first round on
  MeshStats stats;
  const Mesh one = mesh_with_threads(*s, settings, 1, &stats);
  ASSERT_GE(one.vertex_count(), 55000u);
  test::expect_floor(one, *s, analyze_quality(one, s.get()), 0);
  const Mesh two = mesh_with_threads(*s, settings, 2);
  EXPECT_EQ(one.positions, two.positions);
  EXPECT_EQ(one.triangles, two.triangles);
}

TEST(LargeMeshOrder, VerticesOnTheBoxFacesStayOnThem) {
  const SurfacePtr s = test::tanglecube();
  Settings settings;
  settings.edge_length = 0.035;
  settings.box = Box{Vec3(-2.6, -2.6, -2.6), Vec3(2.6, 2.6, 0.5)};  // cuts the surface at z = 0.5
  const Mesh one = mesh_with_threads(*s, settings, 1);
  ASSERT_GE(one.vertex_count(), 50000u);
  const QualityReport q = analyze_quality(one, s.get());
  EXPECT_EQ(test::count_self_intersections(one), 0u);
  EXPECT_LT(test::max_vertex_distance(*s, one), 1e-9 * s->box().diagonal());
  EXPECT_GE(q.shape.min_angle.min, 20.0);
  const TopologyReport t = analyze_topology(one);
  EXPECT_TRUE(t.manifold() && t.consistently_oriented());
  EXPECT_FALSE(t.watertight());
  // Every vertex of a boundary edge (an edge of one triangle) lies on a face of the box, most on the cut.
  const Box& box = *settings.box;
  const auto on_a_face = [&](const Vec3& p) {
    for (int a = 0; a < 3; ++a)
      if (std::abs(p[a] - box.lo[a]) < 1e-9 || std::abs(p[a] - box.hi[a]) < 1e-9) return true;
    return false;
  };
  const std::set<std::uint32_t> boundary = test::boundary_vertices(one);
  std::size_t on_cut = 0;
  for (const std::uint32_t v : boundary) {
    EXPECT_TRUE(on_a_face(one.positions[v])) << "vertex " << v;
    if (std::abs(one.positions[v].z() - 0.5) < 1e-12) ++on_cut;
  }
  EXPECT_GT(boundary.size(), 200u);
  EXPECT_GT(on_cut, boundary.size() / 2);
  const Mesh two = mesh_with_threads(*s, settings, 2);
  EXPECT_EQ(one.positions, two.positions);
  EXPECT_EQ(one.triangles, two.triangles);
}

}  // namespace
}  // namespace isopatch
