// Composite surfaces refined (composite/composite_refinement.hpp, and the automatic level of
// mesh_composite()): every example refined keeps its topology, every vertex on its own patch's
// function, the curves' points exactly the curves' own samples; the automatic level is no worse than one
// level; the same bytes for any thread count.
#include <isopatch/composite_mesh.hpp>
#include <isopatch/error.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/composite_quality.hpp"
#include "composite_mesher/composite_mesher.hpp"
#include "composite_mesher/composite_refinement.hpp"
#include "composite_mesher/curve_samples.hpp"
#include "composite_model/ipatch_file.hpp"
#include "example_files.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

class RefinedExamples : public ::testing::TestWithParam<std::string> {};

TEST_P(RefinedExamples, KeepTopologyPatchesAndCurves) {
  const Composite c = read_ipatch(test::example_path(GetParam()));
  Settings s;
  s.edge_length = c.box.diagonal() / 45.0;
  const CompositeMesh base = mesh_composite_projection(c, s);
  constexpr int kLevel = 2;
  refine::RefineParams params;
  params.level = kLevel;
  CompositeMesh refined;
  const refine::RefineResult r = refine_composite(c, base, params, &refined);
  ASSERT_EQ(r.failed_points, 0u);
  // Every base triangle cut into k^2, every base edge into k: V' = V + (k-1) E + (k-1)(k-2)/2 T.
  const std::size_t edges = base.mesh.triangle_count() * 3 / 2;
  EXPECT_EQ(refined.mesh.vertex_count(), base.mesh.vertex_count() + (kLevel - 1) * edges +
                                             (kLevel - 1) * (kLevel - 2) / 2 * base.mesh.triangle_count());
  EXPECT_EQ(refined.mesh.triangle_count(), base.mesh.triangle_count() * kLevel * kLevel);

  const TopologyReport before = analyze_topology(base.mesh);
  const TopologyReport after = analyze_topology(refined.mesh);
  EXPECT_TRUE(after.watertight());
  EXPECT_TRUE(after.manifold());
  EXPECT_TRUE(after.consistently_oriented());
  EXPECT_TRUE(after.outward_oriented());
  EXPECT_EQ(after.genus, before.genus);
  EXPECT_EQ(after.components.size(), before.components.size());
  EXPECT_EQ(after.duplicate_vertices, 0u);
  EXPECT_EQ(test::count_self_intersections(refined.mesh), 0u);

  // A curve's vertices are the base's samples with the curve's own samples at k times its segments
  // between them, bit for bit, and lie in no patch's interior; every other vertex is on its own patch's
  // function.
  for (std::size_t curve = 0; curve < c.curves.size(); ++curve) {
    const auto& ids = refined.curve_vertices[curve];
    if (ids.empty()) continue;
    ASSERT_EQ(refined.curve_segments[curve], kLevel * base.curve_segments[curve]);
    const std::vector<Vec3> coarse = sample_arc(c.curves[curve], base.curve_segments[curve]);
    const std::vector<Vec3> fine = sample_arc(c.curves[curve], refined.curve_segments[curve]);
    ASSERT_EQ(ids.size(), fine.size());
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const Vec3& expected = i % kLevel == 0 ? coarse[i / kLevel] : fine[i];
      EXPECT_EQ(refined.mesh.positions[ids[i]], expected) << "curve " << curve << " sample " << i;
      EXPECT_LT(refined.vertex_patch[ids[i]], 0);
    }
  }
  const CompositeQuality q0 = measure_composite_mesh(c, base);
  const CompositeQuality q = measure_composite_mesh(c, refined);
  EXPECT_LE(q.max_relative_distance, 1e-9);
  EXPECT_LT(q.seam_gradient_angle, 1e-3);
  // The refinement adds vertices of valence 6 only.
  EXPECT_GE(q.patch_valence_6, q0.patch_valence_6);
  EXPECT_GT(q.min_angle, 10.0);
  std::printf(
      "%s refined by %d: %zu -> %zu vertices, valence 6 inside patches %.1f%% -> %.1f%%, smallest "
      "angle %.2f -> %.2f\n",
      GetParam().c_str(), kLevel, base.mesh.vertex_count(), refined.mesh.vertex_count(),
      100.0 * q0.patch_valence_6, 100.0 * q.patch_valence_6, q0.min_angle, q.min_angle);
}

TEST_P(RefinedExamples, AutomaticLevelIsNoWorseThanOneLevel) {
  const CompositeModel model = read_composite(test::example_path(GetParam()));
  Settings one;
  one.edge_length = model.composite().box.diagonal() / 120.0;
  one.refine = 1;
  Settings automatic = one;
  automatic.refine = 0;
  MeshStats stats;
  const Mesh single = mesh_composite(model, one);
  const Mesh refined = mesh_composite(model, automatic, &stats);
  ASSERT_TRUE(stats.refine);
  const ShapeReport a = analyze_shape(single), b = analyze_shape(refined);
  const ValenceReport va = analyze_valence(single), vb = analyze_valence(refined);
  std::printf(
      "%s: level %d (first %d, %d bases), %zu / %zu vertices, valence 6 %.2f%% / %.2f%%, smallest "
      "angle %.2f / %.2f\n",
      GetParam().c_str(), stats.refine->level, stats.refine->first_level, stats.refine->attempts,
      refined.vertex_count(), single.vertex_count(), 100.0 * vb.share_6, 100.0 * va.share_6, b.min_angle.min,
      a.min_angle.min);
  EXPECT_TRUE(analyze_topology(refined).watertight());
  EXPECT_GE(b.min_angle.min, std::min(a.min_angle.min, 20.0));
  EXPECT_GE(vb.share_6, va.share_6 - 0.005);
  if (stats.refine->level == 1) {
    EXPECT_EQ(refined.positions, single.positions);
  }
}

INSTANTIATE_TEST_SUITE_P(Composite, RefinedExamples, ::testing::ValuesIn(test::example_files()),
                         [](const auto& param_info) {
                           return param_info.param.substr(0, param_info.param.size() - 7);
                         });

TEST(CompositeRefinement, SameBytesForAnyThreadCountAndAnExplicitLevel) {
  const CompositeModel model = read_composite(test::example_path("cube.ipatch"));
  Settings s;
  s.edge_length = model.composite().box.diagonal() / 150.0;
  s.vertex_roles = true;
  MeshStats stats;
  s.threads = 1;
  const Mesh one = mesh_composite(model, s, &stats);
  ASSERT_TRUE(stats.refine);
  EXPECT_GT(stats.refine->level, 2);  // the cube's patches are gentle: a high level
  s.threads = 3;
  const Mesh three = mesh_composite(model, s);
  EXPECT_EQ(one.positions, three.positions);
  EXPECT_EQ(one.triangles, three.triangles);
  // An explicit level is that level, and the refinement's vertices carry their role.
  s.refine = 2;
  MeshStats fixed;
  const Mesh two = mesh_composite(model, s, &fixed);
  ASSERT_TRUE(fixed.refine);
  EXPECT_EQ(fixed.refine->level, 2);
  const std::vector<float>* role = two.find_attribute("role");
  ASSERT_NE(role, nullptr);
  EXPECT_EQ(static_cast<std::size_t>(std::count(role->begin(), role->end(), 6.0f)),
            two.vertex_count() - fixed.refine->base_vertices);
}

TEST(CompositeRefinement, RefusesAMeshOfAnotherComposite) {
  const Composite cube = read_ipatch(test::example_path("cube.ipatch"));
  const Composite prism = read_ipatch(test::example_path("prism.ipatch"));
  Settings s;
  s.edge_length = cube.box.diagonal() / 30.0;
  const CompositeMesh base = mesh_composite_projection(cube, s);
  refine::RefineParams params;
  EXPECT_THROW(refine_composite(prism, base, params), InputError);
}

}  // namespace
}  // namespace isopatch
