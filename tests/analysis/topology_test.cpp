// analyze_topology on small meshes built by hand, each with a known defect or a known topology.
#include <isopatch/error.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace isopatch {
namespace {

Mesh tetrahedron(Vec3 shift = Vec3::Zero()) {
  Mesh m;
  m.positions = {shift + Vec3(0, 0, 0), shift + Vec3(1, 0, 0), shift + Vec3(0, 1, 0), shift + Vec3(0, 0, 1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

Mesh octahedron() {
  Mesh m;
  m.positions = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

// The unit cube [0,1]^3, two triangles per face, outward.
Mesh cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  // Each face as a quad a b c d, counter-clockwise seen from outside.
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

// A torus of revolution (radii R, r) sampled on an m x n parameter grid, outward.
Mesh torus(int m, int n, double R = 1.0, double r = 0.4) {
  Mesh mesh;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = 2 * std::numbers::pi * i / m;
      const double v = 2 * std::numbers::pi * j / n;
      mesh.positions.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                                  r * std::sin(v));
    }
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % m) * n + (j % n)); };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh;
}

void append(Mesh& to, const Mesh& from) {
  const auto offset = static_cast<std::uint32_t>(to.positions.size());
  to.positions.insert(to.positions.end(), from.positions.begin(), from.positions.end());
  for (Triangle t : from.triangles) to.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

void expect_closed_sphere(const TopologyReport& r) {
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.consistently_oriented());
  EXPECT_TRUE(r.outward_oriented());
  EXPECT_EQ(r.degenerate_triangles, 0u);
  EXPECT_EQ(r.duplicate_vertices, 0u);
  EXPECT_EQ(r.unreferenced_vertices, 0u);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.euler_characteristic, 2);
  EXPECT_EQ(r.genus, 0);
  EXPECT_EQ(r.components[0].genus, 0);
}

TEST(Topology, Tetrahedron) {
  const TopologyReport r = analyze_topology(tetrahedron());
  expect_closed_sphere(r);
  EXPECT_EQ(r.vertices, 4u);
  EXPECT_EQ(r.edges, 6u);
  EXPECT_EQ(r.triangles, 4u);
  EXPECT_NEAR(r.components[0].volume, 1.0 / 6.0, 1e-15);
}

TEST(Topology, Octahedron) {
  const TopologyReport r = analyze_topology(octahedron());
  expect_closed_sphere(r);
  EXPECT_EQ(r.edges, 12u);
  EXPECT_NEAR(r.components[0].volume, 4.0 / 3.0, 1e-14);
}

TEST(Topology, CubeOfTwelveTriangles) {
  const TopologyReport r = analyze_topology(cube());
  expect_closed_sphere(r);
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.edges, 18u);
  EXPECT_EQ(r.triangles, 12u);
  EXPECT_NEAR(r.components[0].volume, 1.0, 1e-14);
}

TEST(Topology, TorusHasGenusOne) {
  const TopologyReport r = analyze_topology(torus(24, 12));
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.outward_oriented());
  EXPECT_EQ(r.euler_characteristic, 0);
  EXPECT_EQ(r.genus, 1);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].genus, 1);
  // Inscribed polyhedron: a little below 2 pi^2 R r^2.
  const double exact = 2 * std::numbers::pi * std::numbers::pi * 0.16;
  EXPECT_LT(r.components[0].volume, exact);
  EXPECT_GT(r.components[0].volume, 0.9 * exact);
}

TEST(Topology, TwoDisjointTetrahedraAreTwoComponents) {
  Mesh m = tetrahedron();
  append(m, tetrahedron(Vec3(3, 0, 0)));
  const TopologyReport r = analyze_topology(m);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.outward_oriented());
  ASSERT_EQ(r.components.size(), 2u);
  EXPECT_EQ(r.euler_characteristic, 4);
  EXPECT_EQ(r.genus, 0);
  for (const ComponentTopology& c : r.components) {
    EXPECT_EQ(c.vertices, 4u);
    EXPECT_EQ(c.edges, 6u);
    EXPECT_EQ(c.triangles, 4u);
    EXPECT_EQ(c.euler_characteristic, 2);
    EXPECT_NEAR(c.volume, 1.0 / 6.0, 1e-14);
  }
}

TEST(Topology, HoleGivesBoundaryEdges) {
  Mesh m = cube();
  m.triangles.erase(m.triangles.begin(), m.triangles.begin() + 2);  // the whole bottom face
  const TopologyReport r = analyze_topology(m);
  EXPECT_FALSE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.consistently_oriented());
  EXPECT_EQ(r.boundary_edges, 4u);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_FALSE(r.components[0].closed());
  EXPECT_EQ(r.components[0].boundary_loops, 1u);
  EXPECT_EQ(r.euler_characteristic, 1);
  EXPECT_EQ(r.components[0].genus, 0);  // a disk: 2 - 2g - b = 1
  EXPECT_EQ(r.genus, 0);                // no closed component
  EXPECT_TRUE(r.outward_oriented());    // open components have no volume sign to check
}

TEST(Topology, TwoHolesAreTwoBoundaryLoops) {
  Mesh m = cube();
  m.triangles.erase(m.triangles.begin(), m.triangles.begin() + 4);  // bottom and top: a tube
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.boundary_edges, 8u);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].boundary_loops, 2u);
  EXPECT_EQ(r.components[0].euler_characteristic, 0);
  EXPECT_EQ(r.components[0].genus, 0);  // an annulus
}

TEST(Topology, FlippedTriangleIsDetected) {
  Mesh m = octahedron();
  std::swap(m.triangles[3][1], m.triangles[3][2]);
  const TopologyReport r = analyze_topology(m);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_FALSE(r.consistently_oriented());
  EXPECT_FALSE(r.outward_oriented());
  EXPECT_EQ(r.inconsistent_edges, 3u);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_FALSE(r.components[0].genus.has_value());
}

TEST(Topology, InwardOrientationHasNegativeVolume) {
  Mesh m = cube();
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  const TopologyReport r = analyze_topology(m);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.consistently_oriented());
  EXPECT_FALSE(r.outward_oriented());
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_NEAR(r.components[0].volume, -1.0, 1e-14);
}

// A hollow cube: the outer wall outward, the wall of the cavity facing into the cavity (negative
// volume). That is the outward orientation of the solid between them; both walls outward, or both
// inward, are not.
TEST(Topology, CavityWallFacesIntoTheCavity) {
  auto scaled_cube = [](double scale, const Vec3& shift, bool inward) {
    Mesh m = cube();
    for (Vec3& p : m.positions) p = scale * p + shift;
    if (inward)
      for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
    return m;
  };
  Mesh hollow = scaled_cube(3.0, Vec3::Zero(), false);
  append(hollow, scaled_cube(1.0, Vec3::Constant(1.0), true));
  const TopologyReport r = analyze_topology(hollow);
  ASSERT_EQ(r.components.size(), 2u);
  EXPECT_TRUE(r.components[0].outward);
  EXPECT_TRUE(r.components[1].outward);
  EXPECT_TRUE(r.outward_oriented());

  Mesh both_out = scaled_cube(3.0, Vec3::Zero(), false);
  append(both_out, scaled_cube(1.0, Vec3::Constant(1.0), false));
  EXPECT_FALSE(analyze_topology(both_out).outward_oriented());

  Mesh both_in = scaled_cube(3.0, Vec3::Zero(), true);
  append(both_in, scaled_cube(1.0, Vec3::Constant(1.0), true));
  EXPECT_FALSE(analyze_topology(both_in).outward_oriented());

  // A cube inside the cavity (three nested walls) is an outer wall again.
  append(hollow, scaled_cube(0.2, Vec3::Constant(1.4), false));
  EXPECT_TRUE(analyze_topology(hollow).outward_oriented());
}

TEST(Topology, NonManifoldEdgeOfThreeTriangles) {
  Mesh m = tetrahedron();
  m.positions.emplace_back(-1, -1, 0);
  m.triangles.push_back({0, 1, 4});  // a fin on edge (0, 1)
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.non_manifold_edges, 1u);
  EXPECT_EQ(r.boundary_edges, 2u);
  EXPECT_FALSE(r.watertight());
  EXPECT_FALSE(r.manifold());
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_FALSE(r.components[0].genus.has_value());
}

TEST(Topology, BowTieVertex) {
  Mesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_FALSE(r.manifold());
  EXPECT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.boundary_edges, 6u);
}

TEST(Topology, TetrahedraSharingOneVertexAreWatertightButNotManifold) {
  Mesh m = tetrahedron();
  append(m, tetrahedron(Vec3(-1, 0, 0)));  // its vertex 1 (index 5) lands on vertex 0 at the origin
  for (Triangle& t : m.triangles)
    for (std::uint32_t& i : t)
      if (i == 5) i = 0;  // glue the two at that point; vertex 5 stays behind, unreferenced
  const TopologyReport r = analyze_topology(m);
  EXPECT_TRUE(r.watertight());
  EXPECT_FALSE(r.manifold());
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  EXPECT_EQ(r.unreferenced_vertices, 1u);
  EXPECT_EQ(r.duplicate_vertices, 1u);
  EXPECT_EQ(r.components.size(), 1u);
  EXPECT_FALSE(r.components[0].genus.has_value());
}

TEST(Topology, DuplicateVertexSplitsTheSurface) {
  Mesh m = tetrahedron();
  m.positions.push_back(m.positions[3]);
  m.triangles[3][2] = 4;  // triangle (1, 2, 3) now uses a copy of vertex 3
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.duplicate_vertices, 1u);
  EXPECT_EQ(r.unreferenced_vertices, 0u);
  EXPECT_EQ(r.boundary_edges, 4u);
  EXPECT_FALSE(r.watertight());
}

TEST(Topology, DegenerateTriangles) {
  Mesh m = tetrahedron();
  m.triangles.push_back({0, 0, 1});  // repeated index: set aside
  m.positions.emplace_back(0.5, 0, 0);
  m.positions.emplace_back(2, 0, 0);
  m.triangles.push_back({1, 4, 5});  // collinear: zero area, but still in the connectivity
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.degenerate_triangles, 2u);
  EXPECT_EQ(r.triangles, 6u);
  EXPECT_EQ(r.boundary_edges, 3u);
  EXPECT_EQ(r.non_manifold_vertices, 1u);  // vertex 1 is a bow tie of the tetrahedron and the sliver
}

TEST(Topology, EmptyMesh) {
  const TopologyReport r = analyze_topology(Mesh{});
  EXPECT_EQ(r.vertices, 0u);
  EXPECT_TRUE(r.components.empty());
  EXPECT_TRUE(r.watertight());
}

TEST(Topology, RejectsBadIndicesAndPositions) {
  Mesh m = tetrahedron();
  m.triangles.push_back({0, 1, 9});
  EXPECT_THROW(analyze_topology(m), InputError);
  m = tetrahedron();
  m.positions[2].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(analyze_topology(m), InputError);
}

TEST(Topology, LargeTorusIsFastAndExact) {
  const Mesh m = torus(400, 300);  // 240,000 triangles
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.triangles, 240000u);
  EXPECT_EQ(r.edges, 360000u);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.outward_oriented());
  EXPECT_EQ(r.genus, 1);
}

}  // namespace
}  // namespace isopatch
