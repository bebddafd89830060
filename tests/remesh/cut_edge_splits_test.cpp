// Splits of long cut edges in the clean-up (src/remesh/cut_edge_splits.hpp): a cut by the box or by a
// region plane is refined to the target size along the curve where f = 0 meets that face or plane, is
// left bit for bit when held, and keeps the tip where a cut curve turns inside a cell.
#include <isopatch/isopatch.hpp>
#include <isopatch/remesh.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "mesh_checks.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace cut_edge_splits_test {

Mesh projection_only(const Surface& s, double edge, const ConvexRegion& region = {}) {
  Settings settings;
  settings.edge_length = edge;
  settings.remesh_iterations = 0;
  settings.region = region;
  return mesh_surface(s, settings);
}

/// The mesh's boundary edges (one triangle each), as vertex pairs.
std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary_edges(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++count[std::minmax(t[k], t[(k + 1) % 3])];
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const auto& [edge, n] : count)
    if (n == 1) out.push_back(edge);
  return out;
}

double longest_boundary_edge(const Mesh& mesh) {
  double longest = 0.0;
  for (const auto& [a, b] : boundary_edges(mesh))
    longest = std::max(longest, (mesh.positions[a] - mesh.positions[b]).norm());
  return longest;
}

std::set<std::uint32_t> boundary_vertices(const Mesh& mesh) {
  std::set<std::uint32_t> out;
  for (const auto& [a, b] : boundary_edges(mesh)) out.insert({a, b});
  return out;
}

TEST(CutEdgeSplits, ABoxCutIsRefinedToTheSizeOnTheBoxAndOnTheSurface) {
  // A tilted plane cut open by its box, meshed at 0.25 and cleaned up to 0.1: the interior splits never
  // touch the boundary, so without cut splits its edges stay about 0.25 long.
  const Box box{Vec3::Constant(-1), Vec3::Constant(1)};
  const auto f = [](auto x, auto y, auto z) { return z - 0.1 * x - 0.05 * y - 0.01; };
  const SurfacePtr plane = make_surface(f, box, "plane");
  Mesh mesh = projection_only(*plane, 0.25);
  const double before = longest_boundary_edge(mesh);
  const std::size_t cut_before = boundary_vertices(mesh).size();
  ASSERT_GT(before, 0.2);
  RemeshSettings r;
  r.sizes.largest = r.sizes.smallest = 0.1;
  r.box = box;
  remesh_on_surface(mesh, *plane, r);
  EXPECT_LE(longest_boundary_edge(mesh), 4.0 / 3.0 * 0.1 + 1e-12);
  const std::set<std::uint32_t> cut = boundary_vertices(mesh);
  EXPECT_GT(2 * cut.size(), 3 * cut_before);
  for (const std::uint32_t v : cut) {
    const Vec3& p = mesh.positions[v];
    EXPECT_TRUE((p.array().abs() == 1.0).any()) << "cut vertex off the box: " << p.transpose();
    EXPECT_LT(std::abs(f(p.x(), p.y(), p.z())), 1e-12);
  }
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.manifold() && t.consistently_oriented());
  EXPECT_EQ(t.euler_characteristic, 1);  // still a disc
  EXPECT_GE(test::min_angle_degrees(mesh), 25.0);
}

TEST(CutEdgeSplits, ARegionPlaneCutIsRefinedOnThePlane) {
  // A sphere cut by a tilted plane of a region: the cut refined along the circle where they meet.
  const SurfacePtr sphere = test::sphere(0.8);
  const Vec3 n = Vec3(1.0, 1.0, 2.0).normalized();
  const ConvexRegion region{{n.x(), n.y(), n.z(), -0.3}};
  Mesh mesh = projection_only(*sphere, 0.25, region);
  ASSERT_GT(longest_boundary_edge(mesh), 0.16);
  RemeshSettings r;
  r.sizes.largest = r.sizes.smallest = 0.08;
  r.box = sphere->box();
  r.cut_planes = region;
  remesh_on_surface(mesh, *sphere, r);
  EXPECT_LE(longest_boundary_edge(mesh), 4.0 / 3.0 * 0.08 + 1e-12);
  for (const std::uint32_t v : boundary_vertices(mesh)) {
    const Vec3& p = mesh.positions[v];
    EXPECT_LT(std::abs(n.dot(p) - 0.3), 1e-9);
    EXPECT_LT(std::abs(p.norm() - 0.8), 1e-9);
  }
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.manifold() && t.consistently_oriented());
  EXPECT_EQ(t.euler_characteristic, 1);
}

TEST(CutEdgeSplits, AHeldCutStaysBitForBit) {
  const Box box{Vec3::Constant(-1), Vec3::Constant(1)};
  const SurfacePtr plane =
      make_surface([](auto x, auto y, auto z) { return z - 0.1 * x - 0.05 * y - 0.01; }, box, "plane");
  Mesh mesh = projection_only(*plane, 0.25);
  std::set<std::vector<double>> before;
  for (const std::uint32_t v : boundary_vertices(mesh)) {
    const Vec3& p = mesh.positions[v];
    before.insert({p.x(), p.y(), p.z()});
  }
  RemeshSettings r;
  r.sizes.largest = r.sizes.smallest = 0.1;
  r.box = box;
  r.hold_cut = true;
  remesh_on_surface(mesh, *plane, r);
  std::set<std::vector<double>> after;
  for (const std::uint32_t v : boundary_vertices(mesh)) {
    const Vec3& p = mesh.positions[v];
    after.insert({p.x(), p.y(), p.z()});
  }
  EXPECT_EQ(before, after);
}

TEST(CutEdgeSplits, CutCurvesTurningInsideACellKeepTheirTips) {
  // Where a box face meets a saddle-shaped surface, the cut curve turns within about 1.6 edges (the tips
  // of U-shaped cut curves of the Neovius surface on the faces of its period box); the mesher's cells
  // crossed such tips with chords of 2-4 edges, cut edges up to 2.2 edges long, and slivers beside them.
  const double pi = std::numbers::pi;
  const Box box{Vec3::Constant(-2.0 * pi), Vec3::Constant(2.0 * pi)};
  const double edge = 4.0 * pi / 60.0;
  for (const std::string formula :
       {"3*(cos(x)+cos(y)+cos(z))+4*cos(x)*cos(y)*cos(z)", "cos(x)*sin(y)+cos(y)*sin(z)+cos(z)*sin(x)"}) {
    SCOPED_TRACE(formula);
    const SurfacePtr f = expression_surface(formula, box);
    Settings settings;
    settings.edge_length = edge;
    const Mesh mesh = mesh_surface(*f, settings);
    EXPECT_LE(longest_boundary_edge(mesh), 1.25 * edge);
    EXPECT_GE(test::min_angle_degrees(mesh), 23.0);
    const TopologyReport t = analyze_topology(mesh);
    EXPECT_TRUE(t.manifold() && t.consistently_oriented());
    for (const std::uint32_t v : boundary_vertices(mesh)) {
      const Vec3& p = mesh.positions[v];
      EXPECT_TRUE(((p.array().abs() - 2.0 * pi).abs() == 0.0).any()) << p.transpose();
    }
  }
}

}  // namespace cut_edge_splits_test
}  // namespace isopatch
