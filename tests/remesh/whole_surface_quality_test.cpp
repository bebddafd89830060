// Issue 7's targets on whole surfaces through the default pipeline (projection + clean-up), at one
// size each: closed, manifold, oriented, right genus, no self-intersections, vertices on f = 0, no
// angle under 20 degrees, at least 90% of interior vertices of valence 6 and mean-curvature nRMS at
// most a fifth of CGAL's (torus 0.015; genus2 has a regression bound, see QualityCase::max_h_nrms).
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "surface_mesh_expectations.hpp"

namespace isopatch {
namespace {

struct QualityCase {
  const char* name;
  SurfacePtr (*make)();
  double edge_length;
  int genus;
  /// Mean-curvature nRMS bound: the target, a fifth of CGAL's at a comparable size (torus 0.015;
  /// tanglecube 0.019, CGAL 0.098 at 10k and 20k vertices in docs/quality.md; 0.0118 measured at 16k
  /// vertices). On genus2 the target (about 0.017) is not met (0.020 measured at 15k vertices): held
  /// to a regression bound a quarter above what it reaches.
  double max_h_nrms;
};

/// The value gtest prints for a case (and gtest_discover_tests appends to the ctest name): readable
/// and stable, instead of a byte dump of the struct with its pointers and padding.
void PrintTo(const QualityCase& c, std::ostream* out) {
  *out << c.name << " at edge length " << c.edge_length;
}

class WholeSurfaceQuality : public ::testing::TestWithParam<QualityCase> {};

TEST_P(WholeSurfaceQuality, MeetsTheTargets) {
  const QualityCase c = GetParam();
  const SurfacePtr s = c.make();
  Settings settings;
  settings.edge_length = c.edge_length;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*s, settings, &stats);
  EXPECT_GE(mesh.vertex_count(), 2000u);
  EXPECT_LE(mesh.vertex_count(), 50000u);
  const QualityReport q = analyze_quality(mesh, s.get());
  test::expect_floor(mesh, *s, q, c.genus);
  EXPECT_EQ(q.shape.share_below_10, 0.0);
  EXPECT_LE(q.accuracy->mean_curvature.nrms, c.max_h_nrms);
}

INSTANTIATE_TEST_SUITE_P(Surfaces, WholeSurfaceQuality,
                         ::testing::Values(QualityCase{"torus", &test::default_torus, 0.04, 1, 0.015},
                                           QualityCase{"tanglecube", &test::tanglecube, 0.09, 5, 0.019},
                                           QualityCase{"genus2", &test::genus2, 0.016, 2, 0.025}),
                         [](const ::testing::TestParamInfo<QualityCase>& param) {
                           return std::string(param.param.name);
                         });

/// Mean-curvature nRMS of the default pipeline's torus mesh at a coarse edge length, and the depth its
/// patches started at.
struct CoarseTorus {
  double h_nrms;
  double depth;
  double depth_steps;
  std::size_t vertices;
};

CoarseTorus coarse_torus(double edge_length, double max_cell_curvature) {
  const SurfacePtr s = test::torus();
  Settings settings;
  settings.edge_length = edge_length;
  settings.max_cell_curvature = max_cell_curvature;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*s, settings, &stats);
  const QualityReport q = analyze_quality(mesh, s.get());
  EXPECT_TRUE(q.topology.watertight());
  EXPECT_EQ(q.topology.genus, 1);
  EXPECT_GE(q.shape.min_angle.min, 20.0);
  EXPECT_GE(q.valence.share_6, 0.90);
  return {q.accuracy->mean_curvature.nrms, static_cast<double>(stats.projection.value().start_depth),
          static_cast<double>(stats.projection.value().curvature_depth_steps), mesh.vertex_count()};
}

// Torus of tube radius 0.4 in a box of side 3.2: at edge length 0.12 the starting cells (0.8) are two
// tube radii long and each patch wraps half the tube. The starting-depth rule begins one level deeper.
// Wrapped patches leave a strained lattice (H nRMS 0.021 at 2k vertices with outlier-only clean-up);
// the clean-up's splits beyond 4/3 h and collapses under 0.7 h remove that strain, so both meet the
// torus target at about 1.4k vertices.
TEST(WholeSurfaceQualityCoarse, PatchesDoNotWrapAroundTheTube) {
  const CoarseTorus deeper = coarse_torus(0.12, Settings{}.max_cell_curvature);
  const CoarseTorus wrapped = coarse_torus(0.12, 0.0);
  EXPECT_EQ(deeper.depth_steps, 1.0);
  EXPECT_EQ(deeper.depth, wrapped.depth + 1.0);
  EXPECT_EQ(wrapped.depth_steps, 0.0);
  EXPECT_LE(deeper.h_nrms, 0.015) << deeper.vertices << " vertices";
  EXPECT_LE(wrapped.h_nrms, 0.015) << wrapped.vertices << " vertices";
}

}  // namespace
}  // namespace isopatch
