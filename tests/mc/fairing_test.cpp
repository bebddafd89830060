// Laplace fairing with re-projection (the paper's Figure 2 baseline): better triangles, same
// connectivity, vertices still on f = 0.
#include <isopatch/fairing.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include "mesh_checks.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace {

TEST(LaplaceFairing, ImprovesAnglesKeepsConnectivityAndStaysOnTheSurface) {
  const auto torus = test::torus();
  Settings settings;
  settings.method = Method::MarchingCubes;
  settings.grid = 32;
  const Mesh before = mesh_surface(*torus, settings);
  Mesh after = before;
  const FairingStats stats = laplace_fair(after, *torus, 10);
  EXPECT_EQ(stats.unconverged, 0u);
  EXPECT_GT(stats.gradient_evaluations, after.vertex_count());
  EXPECT_EQ(after.triangles, before.triangles);
  EXPECT_LT(test::max_vertex_distance(*torus, after), 1e-10);
  const ShapeReport s0 = analyze_shape(before), s1 = analyze_shape(after);
  EXPECT_GT(s1.min_angle.min, 5.0 * s0.min_angle.min);
  EXPECT_LT(s1.share_below_20, s0.share_below_20);
  EXPECT_EQ(analyze_valence(after).share_6, analyze_valence(before).share_6);
  const TopologyReport t = analyze_topology(after);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.outward_oriented());
}

TEST(LaplaceFairing, ThroughTheMeshSettingsAndWithBadIterations) {
  const auto sphere = test::sphere();
  Settings settings;
  settings.method = Method::MarchingCubes;
  settings.grid = 16;
  settings.fair_iterations = 5;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*sphere, settings, &stats);
  ASSERT_TRUE(stats.fairing);
  EXPECT_EQ(stats.fairing->iterations, 5);
  EXPECT_LT(test::max_vertex_distance(*sphere, mesh), 1e-10);
  Mesh copy = mesh;
  EXPECT_THROW(laplace_fair(copy, *sphere, -1), InputError);
  EXPECT_THROW(laplace_fair(copy, *sphere, 10001), InputError);
}

TEST(LaplaceFairing, KeepsBoundaryVerticesOfAClippedMesh) {
  const auto sphere = test::sphere();
  Settings settings;
  settings.method = Method::MarchingCubes;
  settings.grid = 16;
  settings.box = Box{Vec3(0, -1.2, -1.2), Vec3(1.2, 1.2, 1.2)};  // half a sphere, open along x = 0
  const Mesh before = mesh_surface(*sphere, settings);
  Mesh after = before;
  laplace_fair(after, *sphere, 5);
  std::size_t fixed = 0;
  for (std::size_t v = 0; v < before.vertex_count(); ++v) fixed += before.positions[v] == after.positions[v];
  EXPECT_GT(fixed, 0u);
  EXPECT_LT(fixed, before.vertex_count());
}

}  // namespace
}  // namespace isopatch
