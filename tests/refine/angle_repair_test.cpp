// The angle repair, the refinement's last step (refine/angle_repair.hpp): vertices of triangles under the
// floor moved to raise the smallest angle around them, on f = 0, without turning a triangle; the other
// vertices left where they are.
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "../mesh/mesh_fixtures.hpp"
#include "mesh_checks.hpp"
#include "refine/angle_repair.hpp"
#include "refine/lattice_relaxation.hpp"
#include "refine/refine_mesh.hpp"
#include "test_surfaces.hpp"

namespace isopatch::refine {
namespace {

TEST(AngleRepair, RaisesTheSmallestAngleToTheFloorOnTheSurface) {
  const SurfacePtr s = test::sphere();
  RefineParams p;
  p.level = 8;
  p.repair_angle = 0.0;
  const RefineResult r = refine_mesh(test::octahedron(), *s, p);
  ASSERT_EQ(r.failed_points, 0u);
  ASSERT_GT(r.smallest_angle, 30.0);
  // Three vertices pushed along the sphere most of the way to a neighbour: triangles of a few degrees.
  Mesh mesh = r.mesh;
  const std::size_t n = mesh.vertex_count();
  for (const std::size_t v : {n / 4, n / 2, 3 * n / 4}) {
    const auto t = std::find_if(mesh.triangles.begin(), mesh.triangles.end(), [&](const Triangle& tri) {
      return std::find(tri.begin(), tri.end(), v) != tri.end();
    });
    ASSERT_NE(t, mesh.triangles.end());
    const auto corner = static_cast<std::size_t>(std::find(t->begin(), t->end(), v) - t->begin());
    const std::uint32_t next = (*t)[(corner + 1) % 3];
    mesh.positions[v] = (0.2 * mesh.positions[v] + 0.8 * mesh.positions[next]).normalized();
  }
  std::vector<Eigen::Vector3f> normals;
  for (const Vec3& q : mesh.positions) normals.push_back(q.normalized().cast<float>());
  double before = 180.0;
  for (const Triangle& t : mesh.triangles) before = std::min(before, smallest_angle_degrees(mesh, t));
  ASSERT_LT(before, 15.0);
  const Mesh pushed = mesh;
  const Sampler f(*s);
  const Sampler* const functions[] = {&f};
  const std::vector<Motion> motion(mesh.vertex_count(), Motion::Free);
  const std::vector<std::uint32_t> one_function;
  const BoundaryPlanes planes(std::nullopt, ConvexRegion{}, 1e-9);
  const NewtonLimits limits{1e-13, 12, 0.5};
  const AngleRepairInput in{motion, functions, one_function, planes, limits};
  const std::size_t moves = repair_small_angles(mesh, normals, in, 25.0, 10);
  double after = 180.0;
  for (const Triangle& t : mesh.triangles) after = std::min(after, smallest_angle_degrees(mesh, t));
  std::printf("smallest angle %.2f -> %.2f degrees, %zu moves\n", before, after, moves);
  EXPECT_GT(moves, 0u);
  EXPECT_GE(after, 25.0);
  EXPECT_LT(test::max_vertex_distance(*s, mesh), 1e-10);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    EXPECT_TRUE(faces_the_surface(mesh.positions, normals, mesh.triangles[t])) << t;
  // Only vertices of triangles under the floor moved.
  std::vector<bool> near(pushed.vertex_count(), false);
  for (const Triangle& tri : pushed.triangles)
    if (smallest_angle_degrees(pushed, tri) < 25.0)
      for (const std::uint32_t v : tri) near[v] = true;
  for (std::size_t v = 0; v < near.size(); ++v)
    if (!near[v]) {
      ASSERT_EQ(mesh.positions[v], pushed.positions[v]) << v;
    }
  // A higher floor moves vertices again, and the smallest angle never falls: a move is kept only when
  // it raises the smallest angle of its fan.
  EXPECT_GT(repair_small_angles(mesh, normals, in, after + 2.0, 10), 0u);
  double again = 180.0;
  for (const Triangle& t : mesh.triangles) again = std::min(again, smallest_angle_degrees(mesh, t));
  EXPECT_GE(again, after);
  EXPECT_LT(test::max_vertex_distance(*s, mesh), 1e-10);
}

}  // namespace
}  // namespace isopatch::refine
