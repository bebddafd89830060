// The Coons base (Settings::Base::Coons): boundary vertices at equal arc length on the traced face
// curves, interior base points from the multi-sided C0 Coons patch (Salvi 2020), projected along blended
// corner gradients. On strongly curved single-cell patches it spaces the vertices more evenly than the
// barycentric base of Sipos & Salvi 2021, eq. (1).
#include <isopatch/isopatch.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <vector>

#include "mesh_checks.hpp"

namespace isopatch {
namespace {

const Box kUnitCell{Vec3::Zero(), Vec3::Ones()};

Mesh mesh_cell(const Surface& s, int resolution, Settings::Base base, MeshStats& stats) {
  Settings p;
  p.box = kUnitCell;
  p.min_depth = p.max_depth = 0;  // the whole box is one cell
  p.resolution = resolution;
  p.vertex_roles = true;
  p.base = base;
  return mesh_projection(s, p, &stats);
}

/// Coefficient of variation (standard deviation over mean) of the given lengths.
double variation(const std::vector<double>& lengths) {
  double sum = 0.0, sum2 = 0.0;
  for (double l : lengths) {
    sum += l;
    sum2 += l * l;
  }
  const double n = static_cast<double>(lengths.size());
  const double mean = sum / n;
  return std::sqrt(std::max(sum2 / n - mean * mean, 0.0)) / mean;
}

/// Edge lengths of the mesh: all edges, or only those on the boundary (one triangle).
std::vector<double> edge_lengths(const Mesh& mesh, bool boundary_only) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const auto a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<double> lengths;
  for (const auto& [e, count] : edges)
    if (!boundary_only || count == 1)
      lengths.push_back((mesh.positions[e.first] - mesh.positions[e.second]).norm());
  return lengths;
}

double edge_length_variation(const Mesh& mesh) {
  return variation(edge_lengths(mesh, false));
}

void expect_valid_disk(const Surface& s, const Mesh& mesh) {
  EXPECT_LT(test::max_vertex_distance(s, mesh), 1e-10);
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  ASSERT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.components[0].boundary_loops, 1u);
  EXPECT_EQ(t.components[0].genus, 0);
}

TEST(CoonsBase, EighthSphereHasEvenBoundaryAndLessSpreadThanBarycentric) {
  // A sphere of radius 0.6 around cell corner 0: a 3-sided patch bent through 90 degrees along each side.
  const auto s =
      make_surface([](auto x, auto y, auto z) { return x * x + y * y + z * z - 0.36; }, kUnitCell, "corner");
  MeshStats coons_stats, bary_stats;
  const Mesh coons = mesh_cell(*s, 12, Settings::Base::Coons, coons_stats);
  const Mesh bary = mesh_cell(*s, 12, Settings::Base::Barycentric, bary_stats);
  EXPECT_TRUE(coons_stats.projection.value().coons_base);
  EXPECT_FALSE(bary_stats.projection.value().coons_base);
  EXPECT_EQ(coons_stats.projection->patches_by_sides, (std::map<int, std::size_t>{{3, 1}}));
  EXPECT_EQ(coons_stats.projection->fallback_cells, 0u);
  expect_valid_disk(*s, coons);
  EXPECT_EQ(coons.vertex_count(), bary.vertex_count());  // same template, only positions differ

  // Boundary vertices lie exactly in their face planes (near x, y, z = 0; the lattice is offset a little)
  // and, on a circular face curve, equal arc lengths make equal chords: every side's consecutive
  // boundary points are equally far apart.
  const std::vector<float>* roles = coons.find_attribute("role");
  ASSERT_NE(roles, nullptr);
  for (int axis = 0; axis < 3; ++axis) {
    double plane = 1.0;
    for (std::size_t v = 0; v < coons.vertex_count(); ++v)
      if ((*roles)[v] <= 1.0f) plane = std::min(plane, coons.positions[v][axis]);
    std::vector<std::pair<double, Vec3>> side;  // by angle about the axis
    for (std::size_t v = 0; v < coons.vertex_count(); ++v)
      if ((*roles)[v] <= 1.0f && coons.positions[v][axis] == plane) {
        const Vec3& p = coons.positions[v];
        side.emplace_back(std::atan2(p[(axis + 2) % 3], p[(axis + 1) % 3]), p);
      }
    ASSERT_EQ(side.size(), 13u) << "axis " << axis;  // r + 1 points, corners included
    std::sort(side.begin(), side.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    double shortest = 1.0, longest = 0.0;
    for (std::size_t i = 1; i < side.size(); ++i) {
      const double chord = (side[i].second - side[i - 1].second).norm();
      shortest = std::min(shortest, chord);
      longest = std::max(longest, chord);
    }
    EXPECT_LT(longest / shortest, 1.0 + 1e-3) << "axis " << axis;
  }

  const double cv_coons = edge_length_variation(coons), cv_bary = edge_length_variation(bary);
  std::cout << "eighth sphere r = 12: edge-length CV coons " << cv_coons << ", barycentric " << cv_bary
            << "; min angle coons " << test::min_angle_degrees(coons) << ", barycentric "
            << test::min_angle_degrees(bary) << "\n";
  EXPECT_LT(cv_coons, 0.8 * cv_bary);
}

TEST(CoonsBase, SphereCapHasEvenBoundaryEdges) {
  // A sphere of radius 0.77 centred below the cell's bottom face, holding the four bottom corners: a
  // cap crossing the four vertical edges, bent through about 100 degrees between opposite side faces.
  const auto s = make_surface(
      [](auto x, auto y, auto z) {
        return (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) + (z + 0.1) * (z + 0.1) - 0.6;
      },
      kUnitCell, "cap");
  MeshStats coons_stats, bary_stats;
  const Mesh coons = mesh_cell(*s, 10, Settings::Base::Coons, coons_stats);
  const Mesh bary = mesh_cell(*s, 10, Settings::Base::Barycentric, bary_stats);
  EXPECT_EQ(coons_stats.projection.value().fallback_cells, 0u);
  expect_valid_disk(*s, coons);
  EXPECT_EQ(coons_stats.projection->patches_by_sides, (std::map<int, std::size_t>{{4, 1}}));
  // The four face curves are congruent circular arcs (up to the lattice offset): equal arc-length
  // sampling makes all boundary edges nearly equal, unlike rays from evenly spaced chord points.
  const double cv_coons = variation(edge_lengths(coons, true)), cv_bary = variation(edge_lengths(bary, true));
  std::cout << "sphere cap r = 10: boundary edge-length CV coons " << cv_coons << ", barycentric " << cv_bary
            << "; all edges coons " << edge_length_variation(coons) << ", barycentric "
            << edge_length_variation(bary) << "\n";
  EXPECT_LT(cv_coons, 0.01);
  EXPECT_GT(cv_bary, 5.0 * cv_coons);
}

TEST(CoonsBase, SixSidedPatchIsAccepted) {
  const auto s = make_surface(
      [](auto x, auto y, auto z) {
        return x + y + z - 1.5 +
               0.4 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) + (z - 0.5) * (z - 0.5));
      },
      kUnitCell, "tripod");
  MeshStats stats;
  const Mesh mesh = mesh_cell(*s, 10, Settings::Base::Coons, stats);
  EXPECT_EQ(stats.projection.value().patches_by_sides, (std::map<int, std::size_t>{{6, 1}}));
  expect_valid_disk(*s, mesh);
  EXPECT_GT(test::min_angle_degrees(mesh), 15.0);
}

}  // namespace
}  // namespace isopatch
