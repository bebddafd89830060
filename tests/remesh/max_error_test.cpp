// --max-error: a curvature-adapted size field bounds the distance of triangle centroids from f = 0,
// refines the octree where the curvature is high (leaves of several depths) and keeps the mesh valid.
#include <isopatch/catalogue.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <optional>

#include <ostream>
#include <string>

#include "mesh_checks.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

int leaf_depths(const MeshStats& stats) {
  return stats.projection ? static_cast<int>(stats.projection->cells_by_depth.size()) : 0;
}

struct MaxErrorCase {
  const char* name;
  double max_error;
  int genus;
  int min_depths;
};

/// The value gtest prints for a case (and gtest_discover_tests appends to the ctest name): readable
/// and stable, instead of a byte dump of the struct with its pointer and padding.
void PrintTo(const MaxErrorCase& c, std::ostream* out) {
  *out << c.name << " at max error " << c.max_error;
}

class MaxError : public ::testing::TestWithParam<MaxErrorCase> {};

TEST_P(MaxError, CentroidsStayWithinTheBoundOnAValidMesh) {
  const MaxErrorCase c = GetParam();
  const SurfacePtr s = catalogue_surface(c.name);
  Settings settings;
  settings.max_error = c.max_error;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*s, settings, &stats);
  const QualityReport q = analyze_quality(mesh, s.get());
  EXPECT_TRUE(q.topology.watertight() && q.topology.manifold() && q.topology.consistently_oriented());
  EXPECT_EQ(q.topology.genus, c.genus);
  EXPECT_EQ(test::count_self_intersections(mesh), 0u);
  EXPECT_LT(q.accuracy->centroid_distance.max, c.max_error);
  EXPECT_LT(q.accuracy->vertex_distance.max, 1e-9 * s->box().diagonal());
  EXPECT_GE(q.shape.min_angle.min, 20.0);
  EXPECT_GE(leaf_depths(stats), c.min_depths);
}

// Curvature varies on blobby and genus2, so the size field asks for leaves of several depths; the
// sphere's is constant.
INSTANTIATE_TEST_SUITE_P(Surfaces, MaxError,
                         ::testing::Values(MaxErrorCase{"sphere", 1e-3, 0, 1},
                                           MaxErrorCase{"blobby", 1e-3, 0, 3},
                                           MaxErrorCase{"genus2", 1e-3, 2, 3}),
                         [](const ::testing::TestParamInfo<MaxErrorCase>& param) {
                           return std::string(param.param.name);
                         });

TEST(MaxError, HalvingTheBoundRefinesTheMesh) {
  const SurfacePtr s = catalogue_surface("torus");
  Settings coarse, fine;
  coarse.max_error = 4e-3;
  fine.max_error = 1e-3;
  const Mesh a = mesh_surface(*s, coarse);
  const Mesh b = mesh_surface(*s, fine);
  // Sizes go with sqrt(eps): a quarter of the bound needs about four times the vertices.
  const double ratio = static_cast<double>(b.vertex_count()) / static_cast<double>(a.vertex_count());
  EXPECT_GT(ratio, 2.5);
  EXPECT_LT(ratio, 6.5);
  EXPECT_LT(analyze_accuracy(b, *s).centroid_distance.max, 1e-3);
}

// A rounded cube, x^16 + y^16 + z^16 = 1: the curvature changes within an edge across the rounded
// edges, so triangles sized from the curvature at one point overshoot the bound (1.13 EPS at 0.0025
// before the final splits). The splits bring every centroid within the bound, without small angles.
TEST(MaxError, SplitsWhereTheCurvatureChangesWithinAnEdge) {
  const SurfacePtr s =
      resolve_surface("x^16 + y^16 + z^16 - 1", Box{Vec3::Constant(-1.1), Vec3::Constant(1.1)});
  Settings settings;
  settings.max_error = 2.5e-3;
  MeshStats stats;
  const Mesh mesh = mesh_surface(*s, settings, &stats);
  const QualityReport q = analyze_quality(mesh, s.get());
  EXPECT_LT(q.accuracy->centroid_distance.max, 2.5e-3);
  EXPECT_EQ(stats.warnings.error_bound_violations, std::optional<std::size_t>(0));
  EXPECT_GE(q.shape.min_angle.min, 20.0);
  EXPECT_TRUE(q.topology.watertight() && q.topology.manifold() && q.topology.consistently_oriented());
  EXPECT_EQ(q.topology.genus, 0);
}

}  // namespace
}  // namespace isopatch
