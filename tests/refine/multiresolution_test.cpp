// Multiresolution meshing through mesh_surface(): the automatic level, its floor, budgets, cancel,
// progress, regions, frames and the sizes for an error bound.
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>
#include <set>
#include <span>
#include <string>

#include "mesh_checks.hpp"
#include "self_intersection.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace {

void expect_closed_floor(const Mesh& mesh, const Surface& s, int genus, double valence, double angle) {
  const QualityReport q = analyze_quality(mesh, &s);
  EXPECT_TRUE(q.topology.watertight()) << s.name();
  EXPECT_TRUE(q.topology.manifold()) << s.name();
  EXPECT_TRUE(q.topology.outward_oriented()) << s.name();
  EXPECT_EQ(q.topology.components.size(), 1u) << s.name();
  EXPECT_EQ(q.topology.genus, genus) << s.name();
  EXPECT_EQ(test::count_self_intersections(mesh), 0u) << s.name();
  EXPECT_LT(test::max_vertex_distance(s, mesh), 1e-10 * s.box().diagonal()) << s.name();
  EXPECT_GE(q.valence.share_6, valence) << s.name();
  EXPECT_GE(q.shape.min_angle.min, angle) << s.name();
}

/// A mesh with its statistics and its curvature error.
struct MeasuredMesh {
  Mesh mesh;
  MeshStats stats;
  double h_nrms = 0.0;
};

MeasuredMesh mesh_and_measure(const Surface& s, const Settings& settings) {
  MeasuredMesh m;
  m.mesh = mesh_surface(s, settings, &m.stats);
  m.h_nrms = analyze_accuracy(m.mesh, s).mean_curvature.nrms;
  return m;
}

TEST(Multiresolution, DefaultRefinesGentleSurfacesAndHoldsTheFloor) {
  for (const auto& [s, genus] : {std::pair{test::sphere(), 0}, std::pair{test::torus(), 1}}) {
    Settings settings;
    settings.edge_length = 0.03;
    MeshStats stats;
    const Mesh mesh = mesh_surface(*s, settings, &stats);
    ASSERT_TRUE(stats.refine) << s->name();
    EXPECT_GE(stats.refine->level, 4) << s->name();
    EXPECT_EQ(stats.vertices, mesh.vertex_count());
    EXPECT_LT(stats.refine->base_vertices * 10, mesh.vertex_count());
    expect_closed_floor(mesh, *s, genus, 0.97, 25.0);
  }
}

TEST(Multiresolution, TightlyBentSurfacesGetASmallerLevelAndKeepTheFloor) {
  const SurfacePtr s = test::genus2();
  Settings settings;
  settings.edge_length = 0.02;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*s, settings, &stats);
  ASSERT_TRUE(stats.refine);
  // The tube's radius (about 0.1) over the edge allows a few segments at most per base edge.
  EXPECT_LE(stats.refine->level, 3);
  EXPECT_GT(stats.refine->largest_curvature, 5.0);
  expect_closed_floor(mesh, *s, 2, 0.90, 20.0);
}

TEST(Multiresolution, WhereTheCurvatureAsksForLevelOneTheGuardedLevelTwoBeatsIt) {
  // genus2's tubes (curvature about 40) turn the normal by more than 0.4 rad over one edge of 0.014: the
  // curvature alone allows no refinement, but the least automatic level (2) passes the guard and the
  // angle floor, with no higher a curvature error than one level and a quarter of its clean-up.
  const SurfacePtr s = test::genus2();
  Settings settings;
  settings.edge_length = 0.014;
  const MeasuredMesh refined = mesh_and_measure(*s, settings);
  const MeshStats& stats = refined.stats;
  ASSERT_TRUE(stats.refine);
  EXPECT_EQ(stats.refine->level, 2);
  EXPECT_EQ(stats.refine->first_level, 2);  // the grid's first guess: no base thrown away
  EXPECT_EQ(stats.refine->attempts, 1);
  EXPECT_GT(stats.refine->estimated_curvature, 30.0);
  EXPECT_GT(2.0 * *settings.edge_length * stats.refine->largest_curvature, 0.8);  // the default's max_turn
  expect_closed_floor(refined.mesh, *s, 2, 0.97, 25.0);
  settings.refine = 1;
  const MeasuredMesh one = mesh_and_measure(*s, settings);
  EXPECT_LT(stats.gradient_evaluations, one.stats.gradient_evaluations);
  EXPECT_LT(refined.h_nrms, 1.05 * one.h_nrms);
}

TEST(Multiresolution, FineRefinesGentleSurfacesFurtherThanTheDefault) {
  // About 150k vertices on a torus: room for a base of 1000 vertices at level 12.
  const SurfacePtr s = test::torus();
  Settings settings;
  settings.edge_length = 0.011;
  const MeasuredMesh normal = mesh_and_measure(*s, settings);
  settings.quality = Quality::Fine;
  const MeasuredMesh fine = mesh_and_measure(*s, settings);
  ASSERT_TRUE(normal.stats.refine && fine.stats.refine);
  EXPECT_EQ(normal.stats.refine->level, 8);
  EXPECT_EQ(fine.stats.refine->level, 12);
  EXPECT_LT(fine.h_nrms, normal.h_nrms);
  expect_closed_floor(fine.mesh, *s, 1, 0.99, 24.0);  // the fine base's own angles (25 degrees) bent a little
}

TEST(Multiresolution, SameBytesForOneTwoAndFourThreads) {
  const SurfacePtr s = test::tanglecube();
  std::vector<Mesh> meshes;
  for (int threads : {1, 2, 4}) {
    Settings settings;
    settings.threads = threads;
    settings.edge_length = 0.12;
    meshes.push_back(mesh_surface(*s, settings));
  }
  for (std::size_t i = 1; i < meshes.size(); ++i) {
    EXPECT_EQ(meshes[i].triangles, meshes[0].triangles);
    EXPECT_EQ(meshes[i].positions, meshes[0].positions);
  }
}

TEST(Multiresolution, LevelOneAndThePapersMethodAloneAreNotRefined) {
  const SurfacePtr s = test::sphere();
  Settings off;
  off.refine = 1;
  MeshStats stats;
  mesh_surface(*s, off, &stats);
  EXPECT_FALSE(stats.refine);
  Settings paper;
  paper.remesh_iterations = 0;
  mesh_surface(*s, paper, &stats);
  EXPECT_FALSE(stats.refine);
  Settings fixed;
  fixed.refine = 3;
  fixed.remesh_iterations = 0;  // an explicit level refines the raw patches too
  mesh_surface(*s, fixed, &stats);
  ASSERT_TRUE(stats.refine);
  EXPECT_EQ(stats.refine->level, 3);
}

TEST(Multiresolution, ALevelOutOfRangeIsRefusedByName) {
  Settings s;
  s.refine = kMaxRefineLevel + 1;
  try {
    s.validate();
    FAIL() << "no SettingError";
  } catch (const SettingError& e) {
    EXPECT_EQ(e.setting(), "refine");
  }
  s.refine = -1;
  EXPECT_THROW(s.validate(), SettingError);
}

TEST(Multiresolution, AnAbsurdSizeIsRefusedAtOnceWithItsEstimate) {
  Settings settings;
  settings.edge_length = 1e-5;
  settings.max_vertices = 50'000'000;
  const auto start = std::chrono::steady_clock::now();
  try {
    mesh_surface(*test::sphere(), settings);
    FAIL() << "no LimitError";
  } catch (const LimitError& e) {
    EXPECT_EQ(e.setting(), "max_vertices");
    // 2 A / (sqrt(3) h^2) for the unit sphere: 1.45e11.
    EXPECT_NE(std::string(e.what()).find("about 1.4"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);
  // The estimate is not a refusal of what fits: 20k vertices in a budget of 40k.
  settings.edge_length = 0.025;
  settings.max_vertices = 40'000;
  MeshStats with_estimate, without_estimate;
  EXPECT_NO_THROW(mesh_surface(*test::sphere(), settings, &with_estimate));
  // The estimate's evaluations (a 32-cell grid) are in the run's statistics; with an explicit level
  // the estimate is made for the budget alone.
  ASSERT_TRUE(with_estimate.refine.has_value());
  EXPECT_NEAR(with_estimate.refine->estimated_curvature, 1.0, 0.1);  // the unit sphere's, from the grid
  EXPECT_EQ(with_estimate.refine->attempts, 1);                      // the first guess needs no second base
  settings.refine = with_estimate.refine->level;
  settings.max_vertices = 0;
  mesh_surface(*test::sphere(), settings, &without_estimate);
  EXPECT_GE(with_estimate.value_evaluations, without_estimate.value_evaluations + 32 * 32 * 32);
  EXPECT_EQ(without_estimate.refine->estimated_curvature, 0.0);
}

TEST(Multiresolution, ProgressNamesTheStagesAndCancelStopsTheRefinement) {
  std::set<std::string> stages;
  std::atomic<bool> cancel{false};
  Settings settings;
  settings.edge_length = 0.03;
  settings.cancel = &cancel;
  settings.progress = [&](const Progress& p) {
    if (p.stage) stages.insert(p.stage);
    if (p.stage && std::string(p.stage) == "refine" && p.done > 0) cancel = true;
  };
  try {
    mesh_surface(*test::torus(), settings);
    FAIL() << "not cancelled";
  } catch (const LimitError& e) {
    EXPECT_EQ(std::string(e.what()), "cancelled");
  }
  EXPECT_TRUE(stages.count("cleanup"));
  EXPECT_TRUE(stages.count("refine"));
}

/// Forwards to a surface and counts every evaluation the way the evaluation budget does (each value,
/// gradient, Hessian and interval bound is one).
class CountingSurface final : public Surface {
 public:
  explicit CountingSurface(const Surface& inner) : Surface(inner.name(), inner.box()), inner_(inner) {}
  double value(const Vec3& p) const override { return ++count, inner_.value(p); }
  void values(std::span<const Vec3> points, std::span<double> out) const override {
    count += points.size();
    inner_.values(points, out);
  }
  ValueGradient value_gradient(const Vec3& p) const override { return ++count, inner_.value_gradient(p); }
  void value_gradients(std::span<const Vec3> points, std::span<ValueGradient> out) const override {
    count += points.size();
    inner_.value_gradients(points, out);
  }
  SecondOrder second_order(const Vec3& p) const override { return ++count, inner_.second_order(p); }
  std::optional<Interval> bound(const Box& box) const override { return ++count, inner_.bound(box); }
  std::optional<IntervalGradient> gradient_bound(const Box& box) const override {
    return ++count, inner_.gradient_bound(box);
  }
  mutable std::atomic<std::uint64_t> count{0};

 private:
  const Surface& inner_;
};

TEST(Multiresolution, AnEvaluationBudgetStopsItInsideTheRefinement) {
  // A budget that everything before the refinement fits in, with half of the refinement's evaluations
  // to spare: the run must stop inside the refinement.
  const SurfacePtr torus = test::torus();
  const CountingSurface counted(*torus);
  std::uint64_t before_refinement = 0;
  Settings settings;
  settings.edge_length = 0.03;
  settings.progress = [&](const Progress& p) {
    if (p.stage && std::string(p.stage) == "refine" && before_refinement == 0)
      before_refinement = counted.count;
  };
  mesh_surface(counted, settings);
  const std::uint64_t total = counted.count;
  ASSERT_GT(before_refinement, 0u);
  ASSERT_GT(total, before_refinement + 100);
  settings.max_evaluations = before_refinement + (total - before_refinement) / 2;
  bool reached_refinement = false;
  settings.progress = [&](const Progress& p) {
    if (p.stage && std::string(p.stage) == "refine") reached_refinement = true;
  };
  try {
    mesh_surface(*torus, settings);
    FAIL() << "the budget of " << settings.max_evaluations << " evaluations was not enforced";
  } catch (const LimitError& e) {
    EXPECT_EQ(e.setting(), "max_evaluations") << e.what();
  }
  EXPECT_TRUE(reached_refinement);
}

TEST(Multiresolution, ARegionPlaneAndAFrameKeepTheCutAndTheFloor) {
  const SurfacePtr s = test::sphere();
  Settings settings;
  settings.edge_length = 0.04;
  settings.region = {HalfSpace{1.0, 1.0, 1.0, -0.5}};  // x + y + z <= 0.5
  MeshStats stats;
  const Mesh mesh = mesh_surface(*s, settings, &stats);
  ASSERT_TRUE(stats.refine);
  EXPECT_GE(stats.refine->level, 2);
  const std::set<std::uint32_t> boundary = test::boundary_vertices(mesh);
  ASSERT_GT(boundary.size(), 50u);
  for (const std::uint32_t v : boundary) {
    const Vec3& p = mesh.positions[v];
    EXPECT_LT(std::abs(p.sum() - 0.5), 1e-8) << "vertex " << v;
    EXPECT_LT(std::abs(p.squaredNorm() - 1.0), 1e-9) << "vertex " << v;
  }
  EXPECT_GE(test::min_angle_degrees(mesh), 20.0);

  Settings rotated;
  rotated.edge_length = 0.04;
  rotated.frame = Frame{30.0, 20.0, 10.0};
  MeshStats rotated_stats;
  const Mesh turned = mesh_surface(*test::torus(), rotated, &rotated_stats);
  ASSERT_TRUE(rotated_stats.refine);
  expect_closed_floor(turned, *test::torus(), 1, 0.97, 25.0);
}

TEST(Multiresolution, AnErrorBoundIsSingleLevelByDefaultAndAGivenLevelGradesTheBase) {
  const SurfacePtr s = test::torus();
  Settings settings;
  settings.max_error = 2e-4;
  MeshStats automatic;
  mesh_surface(*s, settings, &automatic);
  ASSERT_TRUE(automatic.refine);
  EXPECT_EQ(automatic.refine->level, 1);
  settings.refine = 4;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*s, settings, &stats);
  ASSERT_TRUE(stats.refine);
  EXPECT_EQ(stats.refine->level, 4);
  const QualityReport q = analyze_quality(mesh, s.get());
  // Centroids within the bound (the clean-up's own margin: 4/3 longer edges than the size allows).
  EXPECT_LE(q.accuracy->centroid_distance.max, 2.0 * 2e-4);
  EXPECT_TRUE(q.topology.watertight());
  EXPECT_GE(q.shape.min_angle.min, 20.0);
}

}  // namespace
}  // namespace isopatch
