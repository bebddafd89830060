// The projection mesher over general convex cells (issue 21): n-sided patches in single cells for
// n = 3..16, a sphere clipped by regions (boundary on the region's planes), and the errors of bad
// regions and cells, through mesh_surface.
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "mesh_checks.hpp"
#include "partition/lattice.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

using test::count_self_intersections;
using test::max_vertex_distance;
using test::min_angle_degrees;
using test::valences;

struct BoundaryReport {
  std::size_t edges = 0, vertices = 0, loops = 0;
  bool every_vertex_of_degree_two = true;
  double worst_plane_distance = 0.0;  ///< of the boundary vertices to their nearest plane
  std::size_t edges_off_one_plane = 0;
  std::set<std::uint32_t> boundary_vertices;
};

double plane_distance(const HalfSpace& h, const Vec3& p) {
  const Vec3 n(h.a, h.b, h.c);
  return (n.dot(p) + h.d) / n.norm();
}

BoundaryReport boundary(const Mesh& mesh, const ConvexRegion& planes, double tolerance) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  BoundaryReport r;
  std::map<std::uint32_t, std::vector<std::uint32_t>> adjacent;
  for (const auto& [e, n] : count) {
    if (n != 1) continue;
    ++r.edges;
    adjacent[e.first].push_back(e.second);
    adjacent[e.second].push_back(e.first);
    bool on_one = false;
    for (const HalfSpace& h : planes)
      on_one = on_one || (std::abs(plane_distance(h, mesh.positions[e.first])) <= tolerance &&
                          std::abs(plane_distance(h, mesh.positions[e.second])) <= tolerance);
    r.edges_off_one_plane += on_one ? 0 : 1;
  }
  std::set<std::uint32_t> seen;
  for (const auto& [v, next] : adjacent) {
    r.boundary_vertices.insert(v);
    r.every_vertex_of_degree_two = r.every_vertex_of_degree_two && next.size() == 2;
    double nearest = INFINITY;
    for (const HalfSpace& h : planes)
      nearest = std::min(nearest, std::abs(plane_distance(h, mesh.positions[v])));
    r.worst_plane_distance = std::max(r.worst_plane_distance, nearest);
    if (seen.count(v)) continue;
    ++r.loops;
    std::vector<std::uint32_t> stack{v};
    while (!stack.empty()) {
      const std::uint32_t x = stack.back();
      stack.pop_back();
      if (!seen.insert(x).second) continue;
      for (std::uint32_t y : adjacent[x]) stack.push_back(y);
    }
  }
  r.vertices = adjacent.size();
  return r;
}

/// The smallest angle (degrees) over the triangles that touch no boundary vertex.
double interior_min_angle(const Mesh& mesh, const std::set<std::uint32_t>& boundary_vertices) {
  Mesh inner;
  inner.positions = mesh.positions;
  for (const Triangle& t : mesh.triangles)
    if (!boundary_vertices.count(t[0]) && !boundary_vertices.count(t[1]) && !boundary_vertices.count(t[2]))
      inner.triangles.push_back(t);
  return min_angle_degrees(inner);
}

// --- n-sided patches --------------------------------------------------------------------------------

/// An n-gon prism (inscribed radius r) surrounded by a ring of n trapezoidal prisms out to radius R:
/// the surface crosses the n vertical edges of the middle cell (one n-sided patch) and each ring cell
/// in a quadrilateral.
std::vector<ConvexRegion> prism_and_ring(int n, double r, double R) {
  std::vector<ConvexRegion> cells;
  ConvexRegion middle;
  const double step = 2.0 * std::numbers::pi / n;
  for (int k = 0; k < n; ++k) middle.push_back({std::cos(k * step), std::sin(k * step), 0.0, -r});
  cells.push_back(middle);
  for (int k = 0; k < n; ++k) {
    const double theta = k * step, before = theta - 0.5 * step, after = theta + 0.5 * step;
    cells.push_back({{-std::cos(theta), -std::sin(theta), 0.0, r},
                     {std::cos(theta), std::sin(theta), 0.0, -R},
                     {-std::sin(after), std::cos(after), 0.0, 0.0},
                     {std::sin(before), -std::cos(before), 0.0, 0.0}});
  }
  return cells;
}

TEST(ConvexMesh, NSidedPatchesInSingleCellsWithNeighbours) {
  const double r = 0.5, R = 1.0;
  for (int n = 3; n <= 16; ++n) {
    SCOPED_TRACE("n = " + std::to_string(n));
    const double outer = R / std::cos(std::numbers::pi / n) + 0.01;
    const Box box{Vec3(-outer, -outer, -1.0), Vec3(outer, outer, 1.0)};
    const SurfacePtr f = resolve_surface("z - 0.2 - 0.1*x + 0.05*y + 0.15*(x^2 + y^2)", box, {});
    Settings s;
    s.box = box;
    s.cells = prism_and_ring(n, r, R);
    s.resolution = 6;
    s.remesh_iterations = 0;
    s.vertex_roles = true;
    MeshStats stats;
    const Mesh mesh = mesh_surface(*f, s, &stats);
    ASSERT_TRUE(stats.projection);
    const auto& by_sides = stats.projection->patches_by_sides;
    // One n-sided patch (the middle cell) and n quadrilaterals (the ring): nothing refined or fanned.
    EXPECT_EQ(stats.projection->fallback_cells, 0u);
    EXPECT_EQ(stats.projection->refinements, 0u);
    if (n == 4) {
      EXPECT_EQ(by_sides.at(4), 5u);
    } else {
      EXPECT_EQ(by_sides.at(n), 1u);
      EXPECT_EQ(by_sides.at(4), static_cast<std::size_t>(n));
    }
    // Watertight with its neighbours: one disc whose only boundary is the ring's outside.
    const TopologyReport topo = analyze_topology(mesh);
    EXPECT_TRUE(topo.manifold());
    EXPECT_TRUE(topo.consistently_oriented());
    EXPECT_EQ(topo.components.size(), 1u);
    EXPECT_EQ(topo.euler_characteristic, 1);
    ConvexRegion outside;
    for (int k = 0; k < n; ++k)
      outside.push_back(
          {std::cos(2 * std::numbers::pi * k / n), std::sin(2 * std::numbers::pi * k / n), 0.0, -R});
    const BoundaryReport b = boundary(mesh, outside, 1e-12 * box.diagonal());
    EXPECT_EQ(b.loops, 1u);
    EXPECT_EQ(b.edges_off_one_plane, 0u);
    EXPECT_LE(max_vertex_distance(*f, mesh), 1e-12);
    // Valence 6 inside the middle patch: its interior template vertices away from the centre.
    const std::vector<float>* roles = mesh.find_attribute("role");
    ASSERT_NE(roles, nullptr);
    const std::vector<int> valence = valences(mesh);
    std::size_t inner = 0, six = 0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const Vec3& p = mesh.positions[v];
      if ((*roles)[v] != 2.0f || std::hypot(p.x(), p.y()) > 0.9 * r) continue;  // interior, middle cell
      ++inner;
      six += valence[v] == 6 ? 1 : 0;
    }
    ASSERT_GT(inner, 0u);
    std::printf("n = %2d: %zu of %zu interior vertices of the middle patch of valence 6\n", n, six, inner);
    EXPECT_EQ(six, inner);  // every interior template vertex but the centre (of valence n)
  }
}

// --- regions ----------------------------------------------------------------------------------------

const Box kSphereBox{Vec3::Constant(-1.2), Vec3::Constant(1.2)};

TEST(ConvexMesh, SphereCutThroughItsCentreIsOneDisc) {
  const SurfacePtr f = resolve_surface("sphere", std::nullopt, {});
  Settings s;
  s.box = kSphereBox;
  s.region = {{0, 0, 1, 0}};
  const Mesh mesh = mesh_surface(*f, s);
  const TopologyReport topo = analyze_topology(mesh);
  EXPECT_EQ(topo.components.size(), 1u);
  EXPECT_EQ(topo.euler_characteristic, 1);  // a disc
  EXPECT_TRUE(topo.manifold());
  EXPECT_TRUE(topo.consistently_oriented());
  EXPECT_EQ(count_self_intersections(mesh), 0u);
  const BoundaryReport b = boundary(mesh, s.region, 1e-12 * kSphereBox.diagonal());
  EXPECT_EQ(b.loops, 1u);
  EXPECT_TRUE(b.every_vertex_of_degree_two);
  EXPECT_LE(b.worst_plane_distance, 1e-12 * kSphereBox.diagonal());
  EXPECT_EQ(b.edges_off_one_plane, 0u);
  for (const Vec3& p : mesh.positions) EXPECT_LE(p.z(), 1e-12);
  EXPECT_LE(max_vertex_distance(*f, mesh), 1e-12);
  EXPECT_GE(analyze_valence(mesh).share_6, 0.9);
  EXPECT_GE(interior_min_angle(mesh, b.boundary_vertices), 20.0);
  EXPECT_GE(min_angle_degrees(mesh), 20.0);  // the cut vertices slide along their planes in the clean-up
}

TEST(ConvexMesh, SphereInAPolytopeHasItsBoundaryOnThePlanes) {
  // Six oblique planes at about 0.85 from the centre cut six caps off the unit sphere: a sphere with
  // six holes, each bounded by one loop on one plane.
  const SurfacePtr f = resolve_surface("sphere", std::nullopt, {});
  Settings s;
  s.box = kSphereBox;
  s.region = {{1, 0.2, 0.1, -0.85},  {-1, 0.1, 0.2, -0.85}, {0.1, 1, -0.2, -0.85},
              {0.2, -1, 0.1, -0.85}, {0.1, 0.1, 1, -0.85},  {-0.2, 0.1, -1, -0.85}};
  const Mesh mesh = mesh_surface(*f, s);
  const TopologyReport topo = analyze_topology(mesh);
  EXPECT_EQ(topo.components.size(), 1u);
  EXPECT_EQ(topo.euler_characteristic, 2 - 6);
  EXPECT_TRUE(topo.manifold());
  EXPECT_TRUE(topo.consistently_oriented());
  EXPECT_EQ(count_self_intersections(mesh), 0u);
  const BoundaryReport b = boundary(mesh, s.region, 1e-12 * kSphereBox.diagonal());
  EXPECT_EQ(b.loops, 6u);
  EXPECT_TRUE(b.every_vertex_of_degree_two);
  EXPECT_LE(b.worst_plane_distance, 1e-12 * kSphereBox.diagonal());
  EXPECT_EQ(b.edges_off_one_plane, 0u);
  EXPECT_LE(max_vertex_distance(*f, mesh), 1e-12);
  EXPECT_GE(analyze_valence(mesh).share_6, 0.9);
  EXPECT_GE(interior_min_angle(mesh, b.boundary_vertices), 20.0);
  EXPECT_GE(min_angle_degrees(mesh), 20.0);  // the cut vertices slide along their planes in the clean-up
}

TEST(ConvexMesh, RegionPlaneOnOrNearALatticePlane) {
  // The lattice's middle plane in z (a plane of every depth), and planes 1e-13, 1e-9 and 1e-6 of the box
  // from it: a sliver of cells, or a plane that coincides with their faces. Each is one disc whose
  // boundary lies on the region's plane, and the clean-up leaves no angle under 20 degrees.
  const SurfacePtr f = resolve_surface("sphere", std::nullopt, {});
  const Lattice lattice = make_lattice(kSphereBox, 8);
  const double middle = lattice.point({0, 0, 1u << 7}).z();
  for (double offset : {0.0, 1e-13, 1e-9, -1e-9, 1e-6}) {
    SCOPED_TRACE(offset);
    Settings s;
    s.box = kSphereBox;
    s.region = {{0, 0, 1, -(middle + offset)}};
    const Mesh mesh = mesh_surface(*f, s);
    const TopologyReport topo = analyze_topology(mesh);
    EXPECT_EQ(topo.components.size(), 1u);
    EXPECT_EQ(topo.euler_characteristic, 1);
    EXPECT_TRUE(topo.manifold());
    const BoundaryReport b = boundary(mesh, s.region, 1e-12 * kSphereBox.diagonal());
    EXPECT_EQ(b.loops, 1u);
    EXPECT_EQ(b.edges_off_one_plane, 0u);
    EXPECT_GE(min_angle_degrees(mesh), 20.0);
  }
}

TEST(ConvexMesh, RefinedRegionCellsLeaveNoCracks) {
  // Thin surfaces make the region's cells split: a coarse cell then meets finer ones, and a finer
  // neighbour's vertex inside its face may carry the only sign change it sees. The raw mesh (no
  // clean-up) has its boundary on the region's plane only: no crack between cells of two sizes.
  for (const char* name : {"double_torus", "genus2"}) {
    SCOPED_TRACE(name);
    const SurfacePtr f = resolve_surface(name, std::nullopt, {});
    Settings s;
    s.box = f->box();
    s.region = {{1, 0.3, 0.2, -0.1}};
    s.remesh_iterations = 0;
    MeshStats stats;
    const Mesh mesh = mesh_surface(*f, s, &stats);
    ASSERT_TRUE(stats.projection);
    EXPECT_GT(stats.projection->refinements, 0u);
    const TopologyReport topo = analyze_topology(mesh);
    EXPECT_TRUE(topo.manifold());
    EXPECT_TRUE(topo.consistently_oriented());
    const BoundaryReport b = boundary(mesh, s.region, 1e-12 * s.box->diagonal());
    EXPECT_GT(b.edges, 0u);
    EXPECT_EQ(b.edges_off_one_plane, 0u);
    EXPECT_TRUE(b.every_vertex_of_degree_two);
  }
}

TEST(ConvexMesh, RegionMeshIsTheSameForAnyThreadCount) {
  const SurfacePtr f = resolve_surface("torus", std::nullopt, {});
  Settings s;
  s.box = Box{Vec3(-1.6, -1.6, -0.6), Vec3(1.6, 1.6, 0.6)};
  s.region = {{1, 0, 0, -0.3}, {0, 1, 0.3, -0.2}};
  s.threads = 1;
  const Mesh one = mesh_surface(*f, s);
  s.threads = 2;
  const Mesh two = mesh_surface(*f, s);
  EXPECT_EQ(one.positions, two.positions);
  EXPECT_EQ(one.triangles, two.triangles);
  EXPECT_EQ(analyze_topology(one).components.size(), 1u);
}

// --- bad regions and cells --------------------------------------------------------------------------

std::string setting_of(const Surface& f, const Settings& s) {
  try {
    mesh_surface(f, s);
  } catch (const SettingError& e) {
    return e.setting();
  }
  return "";
}

TEST(ConvexMesh, BadRegionsAndCellsNameTheirSetting) {
  const SurfacePtr f = resolve_surface("sphere", std::nullopt, {});
  Settings s;
  s.region = {{0, 0, 1, 5}};  // z <= -5, no box: misses the surface's own box
  EXPECT_EQ(setting_of(*f, s), "region");
  s.box = kSphereBox;
  s.region = {{0, 0, 1, 5}};  // z <= -5: misses the box
  EXPECT_EQ(setting_of(*f, s), "region");
  s.region = {{0, 0, 0, 1}};  // no normal
  EXPECT_EQ(setting_of(*f, s), "region");
  s.region = {{0, 0, 1, 0}};
  s.method = Method::MarchingCubes;
  EXPECT_EQ(setting_of(*f, s), "method");
  Settings c;
  c.box = kSphereBox;
  c.cells = {{{1, 0, 0, -0.5}}, {{-1, 0, 0, 0.0}}};  // x <= 0.5 and x >= 0 overlap
  EXPECT_EQ(setting_of(*f, c), "cells");
  // A bounded region needs no box: the sphere inside a cube of side 1.6 is closed but for six holes.
  Settings bounded;
  bounded.region = {{1, 0, 0, -0.8},  {-1, 0, 0, -0.8}, {0, 1, 0, -0.8},
                    {0, -1, 0, -0.8}, {0, 0, 1, -0.8},  {0, 0, -1, -0.8}};
  const Mesh mesh = mesh_surface(*f, bounded);
  EXPECT_EQ(analyze_topology(mesh).euler_characteristic, 2 - 6);
}

/// An edge length of a fortieth of the box's longest side (the default is a 64th): the cuts' properties
/// do not depend on the resolution, and the meshes are 2.5 times smaller (these tests also run under
/// the sanitizers).
double coarse_edge_length(const Box& box) {
  return box.size().maxCoeff() / 40.0;
}

// An unbounded region without a box lies inside the surface's own box, as with that box given; in a
// frame too (the region and the surface's box both cut the mesh, and it keeps inside both).
TEST(ConvexMesh, UnboundedRegionWithoutABoxLiesInTheSurfacesBox) {
  for (const char* name : {"torus", "gyroid"}) {
    const SurfacePtr f = resolve_surface(name, std::nullopt, {});
    const Box own = f->box();
    for (const bool framed : {false, true}) {
      Settings s;
      s.edge_length = coarse_edge_length(own);
      s.region = {{0, 0.3, 1, -0.1}};
      if (framed) s.frame = Frame{30, 20, 10};
      const Mesh without = mesh_surface(*f, s);
      s.box = own;
      const Mesh with = mesh_surface(*f, s);
      EXPECT_EQ(without.positions, with.positions) << name << (framed ? " framed" : "");
      EXPECT_EQ(without.triangles, with.triangles) << name << (framed ? " framed" : "");
      ASSERT_GT(without.triangles.size(), 100u) << name;
      const double margin = 1e-12 * own.diagonal();
      for (const Vec3& p : without.positions) {
        ASSERT_TRUE(own.contains(p, margin)) << name << (framed ? " framed " : " ") << p.transpose();
        ASSERT_LE(0.3 * p.y() + p.z() - 0.1, margin * std::sqrt(1.09)) << name;
      }
      EXPECT_EQ(analyze_topology(without).components.size(), 1u) << name << (framed ? " framed" : "");
    }
  }
}

// The gyroid leaves its box, and oblique planes cut it too: its cut runs along the box faces and the
// planes, and turns from one onto the other where they meet. The vertices there stay put in the
// clean-up (none slides along its box face off the plane), so every boundary edge lies on one box
// face or one plane, with and without a rotated frame.
TEST(ConvexMesh, CutsThatTurnFromABoxFaceOntoAPlaneStayOnBoth) {
  const SurfacePtr f = resolve_surface("gyroid", std::nullopt, {});
  const Box box = f->box();
  const ConvexRegion faces = {{-1, 0, 0, box.lo.x()}, {1, 0, 0, -box.hi.x()}, {0, -1, 0, box.lo.y()},
                              {0, 1, 0, -box.hi.y()}, {0, 0, -1, box.lo.z()}, {0, 0, 1, -box.hi.z()}};
  for (const ConvexRegion& region :
       {ConvexRegion{{1, 0.4, 0.3, -0.1}}, ConvexRegion{{1, 0.4, 0.3, -0.1}, {-0.3, 1, 0.5, -0.2}}}) {
    for (const bool framed : {false, true}) {
      SCOPED_TRACE(std::to_string(region.size()) + (framed ? " planes, framed" : " planes"));
      Settings s;
      s.edge_length = coarse_edge_length(box);
      s.region = region;
      if (framed) s.frame = Frame{30, 20, 10};
      const Mesh mesh = mesh_surface(*f, s);
      ConvexRegion all = region;
      all.insert(all.end(), faces.begin(), faces.end());
      const double tol = 1e-12 * box.diagonal();
      const BoundaryReport b = boundary(mesh, all, tol);
      EXPECT_GT(b.edges, 0u);
      EXPECT_EQ(b.edges_off_one_plane, 0u);
      EXPECT_LE(b.worst_plane_distance, tol);
      EXPECT_TRUE(b.every_vertex_of_degree_two);
      EXPECT_EQ(analyze_topology(mesh).components.size(), 1u);
      EXPECT_GE(interior_min_angle(mesh, b.boundary_vertices), 20.0);
    }
  }
}

}  // namespace
}  // namespace isopatch
