// The paper's single-cell examples (Sipos & Salvi 2021, Figures 5-7): a 3-sided and a 6-sided patch in
// one cube cell, meshed by projection and by marching cubes over the same cell.
#include <isopatch/isopatch.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "mesh_checks.hpp"

namespace isopatch {
namespace {

const Box kCell{Vec3::Zero(), Vec3::Ones()};

// Share of valence-6 vertices among the vertices not on the mesh boundary.
double interior_valence6_share(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_count;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const auto a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      ++edge_count[{std::min(a, b), std::max(a, b)}];
    }
  std::set<std::uint32_t> boundary;
  for (const auto& [e, n] : edge_count)
    if (n == 1) boundary.insert({e.first, e.second});
  const std::vector<int> valence = test::valences(mesh);
  std::size_t interior = 0, six = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    if (!boundary.contains(static_cast<std::uint32_t>(v)) && valence[v] > 0) {
      ++interior;
      six += valence[v] == 6;
    }
  return interior ? static_cast<double>(six) / static_cast<double>(interior) : 0.0;
}

struct CellComparison {
  Mesh projection;
  Mesh marching_cubes;
  MeshStats projection_stats;
};

CellComparison mesh_cell(const Surface& s, int resolution, int grid) {
  CellComparison c;
  Settings p;
  p.box = kCell;
  p.min_depth = p.max_depth = 0;  // the whole box is one cell
  p.resolution = resolution;
  p.vertex_roles = true;
  c.projection = mesh_projection(s, p, &c.projection_stats);
  Settings m;
  m.method = Method::MarchingCubes;
  m.box = kCell;
  m.grid = grid;
  c.marching_cubes = marching_cubes(s, m);
  return c;
}

void expect_better_than_mc(const Surface& s, const CellComparison& c) {
  EXPECT_LT(test::max_vertex_distance(s, c.projection), 1e-10);
  const TopologyReport t = analyze_topology(c.projection);
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  ASSERT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.components[0].boundary_loops, 1u);  // one disk clipped by the cell
  EXPECT_EQ(t.components[0].genus, 0);
  EXPECT_GT(interior_valence6_share(c.projection), interior_valence6_share(c.marching_cubes));
  EXPECT_GT(test::min_angle_degrees(c.projection), test::min_angle_degrees(c.marching_cubes));
  EXPECT_GT(test::min_angle_degrees(c.projection), 15.0);
}

TEST(SingleCell, ThreeSidedPatchBeatsMarchingCubes) {
  // An eighth of a sphere around corner 0: the surface crosses the 3 edges at that corner.
  const auto s =
      make_surface([](auto x, auto y, auto z) { return x * x + y * y + z * z - 0.36; }, kCell, "corner");
  const CellComparison c = mesh_cell(*s, 12, 16);
  EXPECT_EQ(c.projection_stats.projection.value().patches_by_sides, (std::map<int, std::size_t>{{3, 1}}));
  expect_better_than_mc(*s, c);
}

TEST(SingleCell, SixSidedPatchBeatsMarchingCubes) {
  // Corner 0 and its three neighbours inside: a tripod configuration, a curved hexagon.
  const auto s = make_surface(
      [](auto x, auto y, auto z) {
        return x + y + z - 1.5 +
               0.4 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) + (z - 0.5) * (z - 0.5));
      },
      kCell, "tripod");
  const CellComparison c = mesh_cell(*s, 10, 16);
  EXPECT_EQ(c.projection_stats.projection.value().patches_by_sides, (std::map<int, std::size_t>{{6, 1}}));
  expect_better_than_mc(*s, c);
}

}  // namespace
}  // namespace isopatch
