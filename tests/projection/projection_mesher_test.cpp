// Whole-surface meshes by projection: topology, accuracy and valence invariants.
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <limits>

#include "mesh_checks.hpp"
#include "self_intersection.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace {

struct MesherCase {
  SurfacePtr surface;
  int genus;
  double edge_length;
  int resolution;
};

void expect_valid_projection_mesh(const MesherCase& c, Settings::Base base = Settings::Base::Barycentric) {
  Settings settings;
  settings.base = base;
  settings.edge_length = c.edge_length;
  settings.resolution = c.resolution;
  settings.vertex_roles = true;
  MeshStats stats;
  const Mesh mesh = mesh_projection(*c.surface, settings, &stats);
  const std::string what = c.surface->name() + " r=" + std::to_string(c.resolution) +
                           (base == Settings::Base::Coons ? " coons" : " barycentric");
  ASSERT_GT(mesh.vertex_count(), 100u) << what;
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.watertight()) << what << ": " << t.boundary_edges << " boundary, " << t.non_manifold_edges
                              << " non-manifold edges";
  EXPECT_TRUE(t.manifold()) << what;
  EXPECT_TRUE(t.outward_oriented()) << what;
  EXPECT_EQ(t.components.size(), 1u) << what;
  EXPECT_EQ(t.genus, c.genus) << what;
  EXPECT_EQ(t.degenerate_triangles, 0u) << what;
  EXPECT_EQ(t.duplicate_vertices, 0u) << what;
  EXPECT_EQ(test::count_self_intersections(mesh), 0u) << what;
  EXPECT_EQ(stats.projection.value().unprojected_vertices, 0u) << what;
  const double diagonal = c.surface->box().diagonal();
  EXPECT_LT(test::max_vertex_distance(*c.surface, mesh), 1e-9 * diagonal) << what;
  // Every interior vertex of a patch has valence 6; only patch centres (role 3) may differ.
  const std::vector<int> valence = test::valences(mesh);
  const std::vector<float>& role = *mesh.find_attribute("role");
  std::size_t interior = 0, regular = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    if (role[v] == 2.0f) {
      ++interior;
      regular += valence[v] == 6;
    }
  EXPECT_GT(interior, 0u) << what;
  EXPECT_EQ(regular, interior) << what;
}

TEST(ProjectionMesher, SphereAtTwoResolutions) {
  expect_valid_projection_mesh({test::sphere(), 0, 0.08, 4});
  expect_valid_projection_mesh({test::sphere(), 0, 0.05, 8});
}

TEST(ProjectionMesher, SphereThroughLatticePoints) {
  // Radius 0.5 centred in [-1,1]^3: without the lattice offset, lattice points lie on f = 0.
  const auto s = make_surface([](auto x, auto y, auto z) { return x * x + y * y + z * z - 0.25; },
                              Box{Vec3::Constant(-1), Vec3::Constant(1)}, "sphere_r05");
  expect_valid_projection_mesh({s, 0, 0.04, 4});
  expect_valid_projection_mesh({s, 0, 0.02, 6});
}

TEST(ProjectionMesher, TorusAtTwoResolutions) {
  expect_valid_projection_mesh({test::torus(), 1, 0.05, 4});
  expect_valid_projection_mesh({test::torus(), 1, 0.05, 8});
}

TEST(ProjectionMesher, TanglecubeAtTwoResolutions) {
  expect_valid_projection_mesh({test::tanglecube(), 5, 0.12, 4});
  expect_valid_projection_mesh({test::tanglecube(), 5, 0.1, 6});
}

TEST(ProjectionMesher, Genus2AtTwoResolutions) {
  expect_valid_projection_mesh({test::genus2(), 2, 0.04, 3});
  expect_valid_projection_mesh({test::genus2(), 2, 0.04, 4});
}

TEST(ProjectionMesher, CoonsBaseKeepsEveryInvariant) {
  expect_valid_projection_mesh({test::sphere(), 0, 0.05, 8}, Settings::Base::Coons);
  expect_valid_projection_mesh({test::torus(), 1, 0.05, 4}, Settings::Base::Coons);
  expect_valid_projection_mesh({test::genus2(), 2, 0.04, 4}, Settings::Base::Coons);
  expect_valid_projection_mesh({test::tanglecube(), 5, 0.1, 6}, Settings::Base::Coons);
}

TEST(ProjectionMesher, RejectsBadSettings) {
  const auto s = test::sphere();
  Settings settings;
  settings.resolution = -1;
  EXPECT_THROW(mesh_projection(*s, settings), InputError);
  settings.resolution = 65;
  EXPECT_THROW(mesh_projection(*s, settings), InputError);
  settings = Settings{};
  settings.edge_length = -1.0;
  EXPECT_THROW(mesh_projection(*s, settings), InputError);
  settings = Settings{};
  settings.min_depth = 5;
  settings.max_depth = 3;
  EXPECT_THROW(mesh_projection(*s, settings), InputError);
  settings = Settings{};
  settings.max_cell_curvature = -0.5;
  EXPECT_THROW(mesh_projection(*s, settings), InputError);
  settings.max_cell_curvature = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(mesh_projection(*s, settings), InputError);
}

TEST(ProjectionMesher, MeanEdgeIsTheRequestedEdgeLength) {
  // Segments per side come from the cell size scaled by the mean side length of the loops at that depth
  // (sides are chords across the cell, shorter than it): the mean edge of the whole pipeline's mesh is
  // the requested length up to the rounding of the segment counts. Counts from the cell size alone gave
  // 0.67-0.77 of it on these surfaces.
  struct Case {
    SurfacePtr surface;
    double edge_length;
  };
  const Case cases[] = {{test::sphere(), 0.05},
                        {test::tanglecube(), 0.16},
                        {test::genus2(), 0.023},
                        {test::genus2(), 0.058},
                        {test::torus(), 0.05}};
  for (const Case& c : cases) {
    Settings settings;
    settings.edge_length = c.edge_length;
    const Mesh mesh = mesh_surface(*c.surface, settings);
    const double mean = analyze_quality(mesh, c.surface.get()).shape.edge_length.mean;
    const std::string what = c.surface->name() + " h=" + std::to_string(c.edge_length);
    EXPECT_GT(mean, 0.85 * c.edge_length) << what << ": mean edge " << mean;
    EXPECT_LT(mean, 1.2 * c.edge_length) << what << ": mean edge " << mean;
  }
}

TEST(ProjectionMesher, StartsDeeperOnlyWhereCellsAreCurved) {
  struct Case {
    SurfacePtr surface;
    double edge_length;
    int resolution;
    double steps;
  };
  // Torus (tube radius 0.4): cells of 0.8 are two radii long, one level deeper they are one radius.
  // Sphere of radius 1: cells of 0.5 turn the normal by half a radian. A fixed resolution keeps the
  // paper's depth. Tiny cells are never split for curvature (at least 3 edge lengths long).
  const Case cases[] = {{test::torus(), 0.12, 0, 1.0},
                        {test::torus(), 0.12, 7, 0.0},
                        {test::sphere(), 0.1, 0, 0.0},
                        {test::torus(), 0.3, 0, 0.0}};
  for (const Case& c : cases) {
    Settings settings;
    settings.edge_length = c.edge_length;
    settings.resolution = c.resolution;
    MeshStats stats;
    const Mesh mesh = mesh_projection(*c.surface, settings, &stats);
    const std::string what =
        c.surface->name() + " h=" + std::to_string(c.edge_length) + " r=" + std::to_string(c.resolution);
    EXPECT_EQ(stats.projection.value().curvature_depth_steps, static_cast<std::size_t>(c.steps)) << what;
    EXPECT_TRUE(analyze_topology(mesh).watertight()) << what;
  }
}

// A sphere of radius 0.01 in a box of side 2 at edge length 0.0007: the edge asks for starting cells
// below the default finest depth (8, cells of 0.0078, two and a half across the sphere), where the
// rejected patches could not be refined and a fan closed them with folded triangles. The refinement
// limit follows the edge length down.
TEST(ProjectionMesher, EdgeLengthBelowTheFinestCellsRaisesTheDepthLimit) {
  const auto s = make_surface([](auto x, auto y, auto z) { return x * x + y * y + z * z - 1e-4; },
                              Box{Vec3::Constant(-1.0), Vec3::Constant(1.0)});
  Settings settings;
  settings.edge_length = 7e-4;
  MeshStats stats;
  const Mesh patches = mesh_projection(*s, settings, &stats);
  EXPECT_GE(stats.projection.value().start_depth, 9);
  EXPECT_EQ(stats.projection->fallback_cells, 0u);
  EXPECT_EQ(test::count_self_intersections(patches), 0u);
  const Mesh mesh = mesh_surface(*s, settings);
  const QualityReport q = analyze_quality(mesh, s.get());
  EXPECT_TRUE(q.topology.watertight() && q.topology.manifold() && q.topology.outward_oriented());
  EXPECT_EQ(q.topology.genus, 0);
  EXPECT_GE(q.shape.min_angle.min, 20.0);
  EXPECT_EQ(test::count_self_intersections(mesh), 0u);
}

// The decocube (genus 13) touches a face plane of the depth-8 lattice at eight points where its tangent
// plane is that face: those faces are ambiguous at every depth, yet each holds one sheet within 2e-4
// of the plane, not two sheets closer than the cell. They are counted as grazing, not as topology in
// doubt (which the command line warns about), while two sheets 0.01 apart stay in doubt.
TEST(ProjectionMesher, FacesTheSurfaceGrazesAreNotTopologyInDoubt) {
  const Box box{Vec3::Constant(-1.4), Vec3::Constant(1.4)};
  const auto decocube = make_surface(
      [](auto x, auto y, auto z) {
        const auto ring = [](auto a, auto b, auto c) {
          return (a * a + b * b - 0.64) * (a * a + b * b - 0.64) + (c * c - 1.0) * (c * c - 1.0);
        };
        return ring(x, y, z) * ring(y, z, x) * ring(z, x, y) - 0.02;
      },
      box);
  Settings settings;
  settings.edge_length = 0.15;
  MeshStats stats;
  const Mesh mesh = mesh_projection(*decocube, settings, &stats);
  EXPECT_GT(stats.warnings.doubtful_grazing_faces, 0u);
  EXPECT_EQ(stats.warnings.doubtful_grazing_faces,
            stats.warnings.doubtful_cells_by_reason.at("ambiguous-face"));
  EXPECT_EQ(stats.warnings.doubtful_topology_cells, 0u);
  EXPECT_EQ(analyze_topology(mesh).genus, 13);

  const auto shell = make_surface(
      [](auto x, auto y, auto z) {
        const auto r2 = x * x + y * y + z * z - 1.0;
        return r2 * r2 - 1e-4;
      },
      Box{Vec3::Constant(-1.5), Vec3::Constant(1.5)});
  settings.max_depth = 4;
  settings.edge_length = 0.3;
  mesh_projection(*shell, settings, &stats);
  EXPECT_GT(stats.warnings.doubtful_topology_cells, 0u);
  EXPECT_EQ(stats.warnings.doubtful_grazing_faces, 0u);
}

TEST(ProjectionMesher, ReportsNoSurfaceAndNaN) {
  const Box box{Vec3::Constant(-1), Vec3::Constant(1)};
  Settings settings;
  settings.max_depth = 4;
  EXPECT_THROW(
      mesh_projection(*make_surface([](auto x, auto y, auto z) { return x * x + y * y + z * z + 1.0; }, box),
                      settings),
      NoSurfaceError);
  EXPECT_THROW(
      mesh_projection(
          *make_surface([](auto x, auto y, auto z) { return sqrt(x) + y * y + z * z - 0.5; }, box), settings),
      EvaluationError);
}

TEST(ProjectionMesher, HonoursVertexBudgetAndCancel) {
  const auto s = test::torus();
  Settings settings;
  settings.max_vertices = 100;
  EXPECT_THROW(mesh_projection(*s, settings), LimitError);
  std::atomic<bool> cancel{true};
  settings = Settings{};
  settings.cancel = &cancel;
  EXPECT_THROW(mesh_projection(*s, settings), LimitError);
}

TEST(ProjectionMesher, AutomaticResolutionFollowsTheEdgeLength) {
  // Halving the edge length roughly quadruples the vertex count, whatever depth is chosen.
  const auto s = test::torus();
  Settings coarse, fine;
  coarse.edge_length = 0.1;
  fine.edge_length = 0.05;
  MeshStats a, b;
  const Mesh m1 = mesh_projection(*s, coarse, &a);
  const Mesh m2 = mesh_projection(*s, fine, &b);
  const double ratio = static_cast<double>(m2.vertex_count()) / static_cast<double>(m1.vertex_count());
  EXPECT_GT(ratio, 2.5);
  EXPECT_LT(ratio, 6.0);
  EXPECT_EQ(a.projection.value().resolution, 0);  // automatic: per side
  EXPECT_GE(a.projection->side_segments_max, 2);
  EXPECT_GE(a.projection->side_segments_min, 1);
}

}  // namespace
}  // namespace isopatch
