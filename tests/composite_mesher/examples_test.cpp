// Every composite in examples/*.ipatch, meshed by projection: closed, manifold, oriented, of the genus
// its curve network has, free of self-intersections, every vertex on its own patch's function, good
// triangles inside the patches, and seams as smooth as the patches' interiors.
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "analysis/composite_quality.hpp"
#include "composite_mesher/composite_mesher.hpp"
#include "composite_model/ipatch_file.hpp"
#include "composite_model/patch_validity.hpp"
#include "example_files.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

/// The genus of the composite's own cell complex (corners, curves, patches), and its boundary curves.
std::pair<int, std::size_t> composite_genus(const Composite& c) {
  std::set<std::array<double, 3>> corners;
  std::vector<int> uses(c.curves.size(), 0);
  for (const ConicArc& a : c.curves) {
    corners.insert({a.start.x(), a.start.y(), a.start.z()});
    corners.insert({a.end.x(), a.end.y(), a.end.z()});
  }
  for (const CompositePatch& p : c.patches)
    for (const PatchSide& s : p.sides) ++uses[s.curve];
  const std::size_t open = static_cast<std::size_t>(std::count(uses.begin(), uses.end(), 1));
  const long euler = static_cast<long>(corners.size()) - static_cast<long>(c.curves.size()) +
                     static_cast<long>(c.patches.size());
  return {static_cast<int>((2 - euler) / 2), open};
}

class Examples : public ::testing::TestWithParam<std::string> {};

TEST_P(Examples, MeshesClosedOnEveryPatchWithSmoothSeams) {
  const Composite c = read_ipatch(test::example_path(GetParam()));
  Settings s;
  s.edge_length = c.box.diagonal() / 90.0;
  MeshStats stats;
  const CompositeMesh m = mesh_composite_projection(c, s, &stats);
  const auto [genus, open_curves] = composite_genus(c);
  const TopologyReport t = analyze_topology(m.mesh);
  EXPECT_EQ(open_curves, 0u);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_TRUE(t.outward_oriented());
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.genus, genus);
  EXPECT_EQ(t.duplicate_vertices, 0u);
  EXPECT_EQ(test::count_self_intersections(m.mesh), 0u);
  const CompositeQuality q = measure_composite_mesh(c, m);
  std::printf(
      "%s: %zu vertices, %zu patches (%zu closed by fans); inside patches valence 6 %.1f%%, smallest "
      "angle %.1f (all %.1f); distance %.1e; normal jump seams %.3f patches %.3f deg/unit, worst seam "
      "%.2f (of the surface itself %.2f); gradient angle at seams %.2e deg\n",
      GetParam().c_str(), m.mesh.vertex_count(), c.patches.size(), stats.warnings.fan_patches,
      100.0 * q.patch_valence_6, q.patch_min_angle, q.min_angle, q.max_relative_distance, q.seam_normal_jump,
      q.patch_normal_jump, q.worst_seam_ratio, q.surface_seam_ratio, q.seam_gradient_angle);
  EXPECT_LE(q.max_relative_distance, 1e-9);
  // The functions meet with G1 continuity at every seam: isophotes are continuous.
  EXPECT_LT(q.seam_gradient_angle, 1e-3);
  // The mesh turns across a seam at most a few times as fast as beside it (a crease: a hundred times
  // and more, see composite_mesher_test.cpp), or as the surface itself does at the mesh's scale.
  EXPECT_LT(q.worst_seam_ratio, 3.0 * std::max(1.0, q.surface_seam_ratio));
  // Every patch meshed by its Coons base and projection (no fan closes a rejected patch), and the
  // validity check finds no fold, extra sheet or bulge on any of them.
  EXPECT_EQ(stats.warnings.fan_patches, 0u);
  for (const PatchFinding& f : check_patch_validity(c)) ADD_FAILURE() << f.message;
  EXPECT_GE(q.patch_valence_6, 0.90);
  EXPECT_GE(q.patch_min_angle, 20.0);
}

INSTANTIATE_TEST_SUITE_P(Composite, Examples, ::testing::ValuesIn(test::example_files()),
                         [](const auto& param_info) {
                           std::string name = param_info.param.substr(0, param_info.param.size() - 7);
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace isopatch
