// Every closed catalogue surface except the singular heart, meshed by projection from its formula (so
// with interval pruning) at two sizes: closed, manifold, outward, right genus, no self-intersections,
// vertices on f = 0, and valence 6 inside every patch.
#include <isopatch/catalogue.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <set>

#include "mesh_checks.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

struct Size {
  double divisions;  ///< edge length = longest box side / divisions
  Settings::Base base;
};

class CatalogueSurface : public ::testing::TestWithParam<std::string> {};

TEST_P(CatalogueSurface, MeshesAreClosedOrientedAndOnTheSurface) {
  const CatalogueEntry& entry = *find_in_catalogue(GetParam());
  const SurfacePtr surface = catalogue_surface(entry.name);
  std::set<int> depths;
  for (const Size size : {Size{40.0, Settings::Base::Barycentric}, Size{64.0, Settings::Base::Coons}}) {
    Settings settings;
    settings.edge_length = entry.box.size().maxCoeff() / size.divisions;
    settings.base = size.base;
    settings.vertex_roles = true;
    MeshStats stats;
    const Mesh mesh = mesh_projection(*surface, settings, &stats);
    const std::string what =
        std::string(entry.name) + " /" + std::to_string(static_cast<int>(size.divisions));
    const TopologyReport t = analyze_topology(mesh);
    EXPECT_TRUE(t.watertight()) << what;
    EXPECT_TRUE(t.manifold()) << what;
    EXPECT_TRUE(t.outward_oriented()) << what;
    EXPECT_EQ(t.components.size(), static_cast<std::size_t>(entry.components)) << what;
    EXPECT_EQ(t.genus, entry.genus) << what;
    EXPECT_EQ(test::count_self_intersections(mesh), 0u) << what;
    EXPECT_LT(test::max_vertex_distance(*surface, mesh), 1e-9 * entry.box.diagonal()) << what;
    const std::vector<int> valence = test::valences(mesh);
    const std::vector<float>& role = *mesh.find_attribute("role");
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
      if (role[v] == 2.0f) {
        ASSERT_EQ(valence[v], 6) << what << " vertex " << v;
      }
    for (const auto& [key, value] : stats.extra)
      if (key.rfind("leaves_depth_", 0) == 0) depths.insert(std::stoi(key.substr(13)));
  }
  RecordProperty("depths", static_cast<int>(depths.size()));
}

INSTANTIATE_TEST_SUITE_P(ClosedSurfaces, CatalogueSurface,
                         ::testing::Values("sphere", "ellipsoid", "torus", "tanglecube", "genus2",
                                           "double_torus", "blobby", "cassini"));

TEST(ChmutovSurface, MeshIsClosedWithTheRightGenus) {
  // Known shortfall: chmutov6's sheets come within a small fraction of a cell of each other near its
  // 28 handles; cells there still fail at the refinement limit and are closed by fans, which are
  // watertight and keep the genus but may intersect neighbouring patches and leave fan centres off
  // f = 0. Asserted here is what holds today.
  const SurfacePtr surface = catalogue_surface("chmutov6");
  Settings settings;
  settings.edge_length = 2.2 / 40.0;
  const Mesh mesh = mesh_projection(*surface, settings);
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.outward_oriented());
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.genus, 28);
}

TEST(AdaptiveProjection, RefinedCellsGiveSeveralLeafDepths) {
  // genus2's thin arms near the waist make cells fail at the starting depth: the refinement is local
  // (leaves of at least three depths) and the mesh stays closed with the right genus.
  const SurfacePtr surface = catalogue_surface("genus2");
  Settings settings;
  settings.edge_length = 2.4 / 40.0;
  MeshStats stats;
  const Mesh mesh = mesh_projection(*surface, settings, &stats);
  int depths = 0;
  for (const auto& [key, value] : stats.extra) depths += key.rfind("leaves_depth_", 0) == 0 && value > 0;
  EXPECT_GE(depths, 3);
  EXPECT_GT(stats.extra.at("flat_corner_leaves"), 0.0);
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.outward_oriented());
  EXPECT_EQ(t.genus, 2);
  EXPECT_EQ(test::count_self_intersections(mesh), 0u);
}

}  // namespace
}  // namespace isopatch
