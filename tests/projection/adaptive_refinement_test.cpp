// Local refinement of the projection mesher on a catalogue surface whose cells fail at the starting
// depth. (The catalogue-wide checks of both meshers are in tests/validation.)
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include "self_intersection.hpp"

namespace isopatch {
namespace {

TEST(AdaptiveProjection, RefinedCellsGiveSeveralLeafDepths) {
  // genus2's thin arms near the waist make cells fail at the starting depth: the refinement is local
  // (leaves of at least three depths) and the mesh stays closed with the right genus.
  const SurfacePtr surface = catalogue_surface("genus2");
  Settings settings;
  settings.edge_length = 2.4 / 40.0;
  MeshStats stats;
  const Mesh mesh = mesh_projection(*surface, settings, &stats);
  ASSERT_TRUE(stats.projection);
  EXPECT_GE(stats.projection->cells_by_depth.size(), 3u);
  EXPECT_GT(stats.projection->flat_corner_cells, 0u);
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.outward_oriented());
  EXPECT_EQ(t.genus, 2);
  EXPECT_EQ(test::count_self_intersections(mesh), 0u);
}

}  // namespace
}  // namespace isopatch
