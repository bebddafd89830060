// The composite path reads every setting that applies to it: a region, a frame and given cells mesh the
// piecewise function through the partition (clipped, rotated, over the caller's cells), and the base
// chooses the Coons patch over the curves or the barycentric combination of the corners; the octree's
// settings are refused along the curves, where they mean nothing.
#include <isopatch/composite_mesh.hpp>
#include <isopatch/error.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "test_composites.hpp"

namespace isopatch {
namespace {

/// Every vertex on the sphere of radius sqrt(3) that the cube sphere's patches lie on.
void expect_on_sphere(const Mesh& mesh) {
  for (const Vec3& p : mesh.positions) ASSERT_NEAR(p.norm(), std::sqrt(3.0), 1e-9);
}

double largest_x(const Mesh& mesh) {
  double x = -1e300;
  for (const Vec3& p : mesh.positions) x = std::max(x, p.x());
  return x;
}

/// A box as six half-spaces.
ConvexRegion box_cell(const Vec3& lo, const Vec3& hi) {
  return {{-1, 0, 0, lo.x()}, {1, 0, 0, -hi.x()}, {0, -1, 0, lo.y()},
          {0, 1, 0, -hi.y()}, {0, 0, -1, lo.z()}, {0, 0, 1, -hi.z()}};
}

Settings base_settings() {
  Settings s;
  s.edge_length = 0.2;
  return s;
}

TEST(CompositeSettings, ARegionClipsTheMeshAtItsPlane) {
  const CompositeModel model(test::cube_sphere());
  Settings s = base_settings();
  const Mesh whole = mesh_composite(model, s);
  EXPECT_GT(largest_x(whole), 1.7);
  s.region = {{1, 0, 0, -0.5}};  // x <= 0.5
  ASSERT_TRUE(meshed_through_partition(s));
  const Mesh clipped = mesh_composite(model, s);
  expect_on_sphere(clipped);
  EXPECT_LE(largest_x(clipped), 0.5 + 1e-9);
  EXPECT_GE(largest_x(clipped), 0.5 - 1e-9);  // the cut's boundary lies on the plane
  const TopologyReport t = analyze_topology(clipped);
  EXPECT_GT(t.boundary_edges, 0u);
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_GT(analyze_shape(clipped).min_angle.min, 15.0);
}

TEST(CompositeSettings, AFrameRotatesThePartitionNotTheSurface) {
  const CompositeModel model(test::cube_sphere());
  Settings s = base_settings();
  s.frame = Frame{30.0, 20.0, 10.0};
  const Mesh rotated = mesh_composite(model, s);
  expect_on_sphere(rotated);
  const TopologyReport t = analyze_topology(rotated);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.outward_oriented());
  EXPECT_EQ(t.genus, 0);
  s.frame.reset();
  EXPECT_NE(mesh_composite(model, s).positions, rotated.positions);
}

TEST(CompositeSettings, GivenCellsPartitionTheComposite) {
  const CompositeModel model(test::cube_sphere());
  Settings s = base_settings();
  s.cells = {box_cell({-2, -2, -2}, {0.3, 2, 2}), box_cell({0.3, -2, -2}, {2, 2, 2})};
  const Mesh mesh = mesh_composite(model, s);
  expect_on_sphere(mesh);
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.watertight());
  EXPECT_EQ(t.genus, 0);
  // Before the clean-up, patch sides lie on the faces of the given cells: some vertices sit on the
  // plane x = 0.3, which neither the composite's curves nor an octree over its box have.
  s.remesh_iterations = 0;
  const Mesh raw = mesh_composite(model, s);
  const auto on_cut = std::count_if(raw.positions.begin(), raw.positions.end(),
                                    [](const Vec3& p) { return std::abs(p.x() - 0.3) < 1e-12; });
  EXPECT_GT(on_cut, 4);
}

TEST(CompositeSettings, TheBaseIsCoonsByDefaultOrBarycentricWhenAsked) {
  const CompositeModel model(test::cube_sphere());
  Settings s = base_settings();
  s.remesh_iterations = 0;  // the patches as projected
  MeshStats automatic_stats, coons_stats, bary_stats;
  const Mesh automatic = mesh_composite(model, s, &automatic_stats);
  s.base = Settings::Base::Coons;
  const Mesh coons = mesh_composite(model, s, &coons_stats);
  s.base = Settings::Base::Barycentric;
  const Mesh bary = mesh_composite(model, s, &bary_stats);
  EXPECT_EQ(automatic.positions, coons.positions);
  ASSERT_TRUE(coons_stats.projection && bary_stats.projection);
  EXPECT_TRUE(coons_stats.projection->coons_base);
  EXPECT_FALSE(bary_stats.projection->coons_base);
  // Other interiors: a flat base projects elsewhere than the curved one.
  EXPECT_NE(bary.positions, coons.positions);
  expect_on_sphere(bary);
  EXPECT_TRUE(analyze_topology(bary).watertight());
  EXPECT_EQ(bary_stats.projection->fallback_cells, 0u);
}

TEST(CompositeSettings, OctreeSettingsAreRefusedAlongTheCurvesAndReadThroughThePartition) {
  const CompositeModel model(test::cube_sphere());
  const auto refused_field = [&](const Settings& s) -> std::string {
    try {
      mesh_composite(model, s);
    } catch (const SettingError& e) {
      return e.setting();
    }
    return "";
  };
  Settings s = base_settings();
  s.max_depth = 6;
  EXPECT_EQ(refused_field(s), "max_depth");
  s = base_settings();
  s.min_depth = 3;
  EXPECT_EQ(refused_field(s), "min_depth");
  s = base_settings();
  s.max_cell_curvature = 0.0;
  EXPECT_EQ(refused_field(s), "max_cell_curvature");
  s = base_settings();
  s.refine_around = {Vec3(1, 1, 1)};
  EXPECT_EQ(refused_field(s), "refine_around");
  // Through the partition the octree reads them: a shallower octree limit still meshes the sphere.
  s = base_settings();
  s.max_depth = 6;
  s.frame = Frame{0.3, 0.2, 0.1};
  const Mesh through = mesh_composite(model, s);
  expect_on_sphere(through);
  EXPECT_TRUE(analyze_topology(through).watertight());
}

}  // namespace
}  // namespace isopatch
