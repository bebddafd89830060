// The surface-bound remesher on its own: settings, sizes for a chordal error, invariants kept.
#include <isopatch/curvature.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/remesh.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "mesh_checks.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace {

Mesh projection_only(const Surface& s, double edge) {
  Settings settings;
  settings.edge_length = edge;
  settings.remesh_iterations = 0;
  return mesh_surface(s, settings);
}

TEST(SizeForError, EquilateralTrianglesOnASphereKeepTheBound) {
  const double radius = 2.0, eps = 1e-3;
  const double h = size_for_error(1.0 / radius, eps);
  EXPECT_NEAR(h, std::sqrt(3.0 * eps * radius), 1e-15);
  // The remesher lets edges reach 4/3 h; the centroid of such an equilateral triangle lies
  // R - sqrt(R^2 - L^2 / 3) below the sphere.
  const double l = 4.0 / 3.0 * h;
  EXPECT_LT(radius - std::sqrt(radius * radius - l * l / 3.0), eps);
  EXPECT_TRUE(std::isinf(size_for_error(0.0, eps)));
}

TEST(SizeForError, MaxCurvatureOfSphereAndTorusIsExact) {
  const SurfacePtr sphere = test::sphere(0.5);
  EXPECT_NEAR(max_abs_principal_curvature(*sphere, Vec3(0.5, 0, 0)), 2.0, 1e-12);
  const SurfacePtr torus = test::torus(1.0, 0.4);
  // Principal curvatures 1/r = 2.5 around the tube and 1/(R + r) outside: the largest is 2.5.
  EXPECT_NEAR(max_abs_principal_curvature(*torus, Vec3(1.4, 0, 0)), 2.5, 1e-9);
}

TEST(Remesh, RejectsInvalidSettings) {
  const SurfacePtr s = test::sphere();
  Mesh mesh = projection_only(*s, 0.2);
  RemeshSettings r;
  EXPECT_THROW(remesh_on_surface(mesh, *s, r), InputError);  // no edge length
  r.sizes.largest = 0.1;
  r.cleanup.remesh_iterations = -1;
  EXPECT_THROW(remesh_on_surface(mesh, *s, r), InputError);
  r.cleanup.remesh_iterations = 2;
  r.sizes.max_error = 0.0;
  EXPECT_THROW(remesh_on_surface(mesh, *s, r), InputError);
  r.sizes.max_error = 1e-3;
  r.sizes.smallest = 0.0;
  EXPECT_THROW(remesh_on_surface(mesh, *s, r), InputError);
  r.sizes.max_error.reset();
  r.cleanup.valence_search = -1;
  EXPECT_THROW(remesh_on_surface(mesh, *s, r), InputError);
  r.cleanup.valence_search = 10001;
  EXPECT_THROW(remesh_on_surface(mesh, *s, r), InputError);
  r.cleanup.valence_search = 30;
  r.cleanup.curvature_sweeps = -1;
  EXPECT_THROW(remesh_on_surface(mesh, *s, r), InputError);
  r.cleanup.curvature_sweeps = 1001;
  EXPECT_THROW(remesh_on_surface(mesh, *s, r), InputError);
  Settings settings;
  settings.remesh_iterations = 101;
  EXPECT_THROW(mesh_surface(*s, settings), InputError);
  settings.remesh_iterations.reset();
  settings.curvature_sweeps = -1;
  EXPECT_THROW(mesh_surface(*s, settings), InputError);
}

TEST(Remesh, ZeroIterationsLeaveTheMeshUnchanged) {
  const SurfacePtr s = test::sphere();
  Mesh mesh = projection_only(*s, 0.15);
  const Mesh before = mesh;
  RemeshSettings r;
  r.sizes.largest = 0.15;
  r.cleanup.remesh_iterations = 0;
  remesh_on_surface(mesh, *s, r);
  EXPECT_EQ(mesh.positions, before.positions);
  EXPECT_EQ(mesh.triangles, before.triangles);
}

TEST(Remesh, KeepsTopologyAndVerticesOnTheSurfaceAndRemovesSmallAngles) {
  const SurfacePtr s = test::torus();
  Mesh mesh = projection_only(*s, 0.08);
  const double before = test::min_angle_degrees(mesh);
  RemeshSettings r;
  r.sizes.largest = 0.08;
  r.box = s->box();
  const RemeshStats stats = remesh_on_surface(mesh, *s, r);
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.watertight() && t.manifold() && t.consistently_oriented());
  EXPECT_EQ(t.genus, 1);
  EXPECT_LT(test::max_vertex_distance(*s, mesh), 1e-9 * s->box().diagonal());
  EXPECT_LT(before, 20.0);  // the projection mesh alone has slivers at seams
  EXPECT_GE(test::min_angle_degrees(mesh), 20.0);
  EXPECT_GT(stats.gradient_evaluations, 0u);
}

TEST(Remesh, SplitsToTheTargetSizeAndKeepsTheBoxBoundary) {
  // A plane cut open by its box: the mesh is refined to the target edge length and stays inside the box.
  const SurfacePtr plane = make_surface([](auto x, auto y, auto z) { return z - 0.1 * x - 0.05 * y - 0.01; },
                                        Box{Vec3::Constant(-1), Vec3::Constant(1)}, "plane");
  Mesh mesh = projection_only(*plane, 0.25);
  std::vector<Vec3> boundary;
  {
    const TopologyReport t = analyze_topology(mesh);
    ASSERT_GT(t.boundary_edges, 0u);
  }
  RemeshSettings r;
  r.sizes.largest = 0.1;
  r.box = plane->box();
  const RemeshStats stats = remesh_on_surface(mesh, *plane, r);
  EXPECT_GT(stats.splits, 0u);
  const ShapeReport shape = analyze_shape(mesh);
  EXPECT_LT(shape.edge_length.median, 2.0 * 0.1);
  for (const Vec3& p : mesh.positions) {
    EXPECT_TRUE((p.array() >= -1.0).all() && (p.array() <= 1.0).all());
  }
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.manifold() && t.consistently_oriented());
  EXPECT_LT(test::max_vertex_distance(*plane, mesh), 1e-12);
}

TEST(Remesh, ValenceSearchPullsApartStuckPairs) {
  // tanglecube at about 2k vertices, where transitions between leaf depths leave many 5-7 pairs: the
  // final sweep of borrowing chains must leave more vertices of valence 6 than skipping it.
  const SurfacePtr s = test::tanglecube();
  Settings settings;
  settings.edge_length = 0.3;
  settings.valence_search = 0;
  const Mesh without = mesh_surface(*s, settings);
  settings.valence_search = 60;
  const Mesh with = mesh_surface(*s, settings);
  const double share_without = analyze_quality(without, s.get()).valence.share_6;
  const double share_with = analyze_quality(with, s.get()).valence.share_6;
  EXPECT_GT(share_with, share_without + 0.01);
  EXPECT_GE(test::min_angle_degrees(with), 20.0);
  const TopologyReport t = analyze_topology(with);
  EXPECT_TRUE(t.watertight() && t.manifold() && t.consistently_oriented());
  EXPECT_EQ(t.genus, 5);
}

TEST(Remesh, CurvatureSweepsLowerTheMeanCurvatureErrorAndKeepTheMeshValid) {
  // The torus at about 9k vertices and an open saddle cut by its box: the Laplacian-exactness sweeps
  // must at least halve the mean-curvature error of the clean-up without them, keep every angle at
  // 20 degrees or more, the topology, the connectivity's valences and the vertices on f = 0.
  struct SweepCase {
    SurfacePtr surface;
    double edge_length;
  };
  const SweepCase cases[] = {{test::torus(), 0.05},
                             {make_surface([](auto x, auto y, auto z) { return z - 0.3 * x * y; },
                                           Box{Vec3::Constant(-1), Vec3::Constant(1)}, "saddle"),
                              0.04}};
  for (const auto& [s, h] : cases) {
    Settings settings;
    settings.refine = 1;  // the clean-up's sweeps at one level
    settings.edge_length = h;
    settings.curvature_sweeps = 0;
    const Mesh without = mesh_surface(*s, settings);
    settings.curvature_sweeps = 12;
    const Mesh with = mesh_surface(*s, settings);
    const QualityReport q_without = analyze_quality(without, s.get());
    const QualityReport q_with = analyze_quality(with, s.get());
    EXPECT_LT(q_with.accuracy->mean_curvature.nrms, 0.5 * q_without.accuracy->mean_curvature.nrms);
    EXPECT_EQ(q_with.valence.share_6, q_without.valence.share_6);  // positions only
    EXPECT_GE(test::min_angle_degrees(with), 20.0);
    EXPECT_LT(test::max_vertex_distance(*s, with), 1e-9 * s->box().diagonal());
    const TopologyReport a = analyze_topology(without), b = analyze_topology(with);
    EXPECT_TRUE(b.manifold() && b.consistently_oriented());
    EXPECT_EQ(a.genus, b.genus);
    ASSERT_EQ(b.components.size(), 1u);
    EXPECT_EQ(a.components[0].boundary_loops, b.components[0].boundary_loops);
  }
}

/// Vertices on edges with one triangle.
std::vector<std::uint32_t> boundary_vertices(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      ++uses[std::minmax(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)])];
  std::set<std::uint32_t> out;
  for (const auto& [edge, count] : uses)
    if (count == 1) out.insert({edge.first, edge.second});
  return {out.begin(), out.end()};
}

TEST(Remesh, BoundaryOfAnOpenSurfaceSlidesAlongTheBoxFacesWithoutSlivers) {
  // A saddle cut open by its box: the projection leaves thin triangles where the cut meets patch
  // corners; the clean-up slides and merges cut vertices along the box faces, so no angle stays under
  // 20 degrees, and the cut stays on the box and on f = 0.
  const Box box{Vec3::Constant(-1), Vec3::Constant(1)};
  const SurfacePtr saddle =
      make_surface([](auto x, auto y, auto z) { return z - 0.3 * x * y; }, box, "saddle");
  const Mesh raw = projection_only(*saddle, 2.0 / 64);
  Settings settings;
  settings.edge_length = 2.0 / 64;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*saddle, settings, &stats);
  EXPECT_LT(test::min_angle_degrees(raw), 20.0);
  EXPECT_GE(test::min_angle_degrees(mesh), 20.0);
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.manifold() && t.consistently_oriented());
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 1);  // still a disk
  EXPECT_LT(test::max_vertex_distance(*saddle, mesh), 1e-9 * box.diagonal());
  const auto cut = boundary_vertices(mesh);
  ASSERT_FALSE(cut.empty());
  int moved = 0;
  for (std::uint32_t v : cut) {
    const Vec3& p = mesh.positions[v];
    EXPECT_TRUE((p.array().abs() == 1.0).any()) << "cut vertex off the box: " << p.transpose();
    bool in_raw = false;
    for (const Vec3& q : raw.positions) in_raw = in_raw || q == p;
    moved += !in_raw;
  }
  EXPECT_GT(moved, 0);  // the cut vertices were not all left where the projection put them
}

}  // namespace
}  // namespace isopatch
