// A shape whose crease paths fail on a feature at the edge's scale meshed along its creases at half the
// edge, then a quarter (api/finer_edge_retry.hpp): a Neovius sheet in a capped cylinder, whose walls'
// creases crowd the caps' rims, closed and exact instead of a rounded, self-intersecting smooth mesh;
// the vertex budget bounds the retry; refusals of other kinds are not retried.
#include <gtest/gtest.h>

#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>

#include <string>
#include <vector>

#include "api/finer_edge_retry.hpp"
#include "part_checks.hpp"

namespace isopatch {
namespace finer_edge_retry_test {

const std::string kNeovius = "3*(cos(x)+cos(y)+cos(z))+4*cos(x)*cos(y)*cos(z)";
const std::string kCylinder = "max(x*x+y*y-9,abs(z)-3)";
const std::string kSheet = "max(abs(" + kNeovius + ")-0.3," + kCylinder + ")";

TEST(FinerEdgeRetry, ARefusalAtTheEdgesScaleIsRetriedOthersAreNot) {
  EXPECT_TRUE(
      finer_edge_may_help("the face of max(a, b) does not close along its boundary on the box near "
                          "(1, 2, 3): creases closer than an edge at the box"));
  EXPECT_TRUE(finer_edge_may_help("a strip between creases narrower than an edge near (0, 0, 0)"));
  EXPECT_FALSE(finer_edge_may_help("the faces do not close up: the shape is not a 2-manifold there"));
  EXPECT_FALSE(finer_edge_may_help("a seam cutting a face into pieces cannot be traced from (0, 0, 0)"));
}

TEST(FinerEdgeRetry, ASheetWhoseCreasesCrowdTheCapsIsMeshedAlongThemAtAQuarterOfTheEdge) {
  // At edge 0.4 (and 0.2) the walls' creases with the cylinder run within an edge of the caps' rims and
  // the join fails; before the retry the shape was meshed smooth, 7 pairs of triangles crossing, 0.00
  // degrees. At 0.1 every path holds.
  const test::CappedRun run = test::mesh_in_cube(kSheet, 3.3, 0.4);
  EXPECT_DOUBLE_EQ(run.stats.warnings.creases_finer_edge, 0.1);
  EXPECT_EQ(run.stats.warnings.creases_rounded, 0u);
  EXPECT_NE(run.stats.warnings.crease_failure.find("than an edge"), std::string::npos);
  const std::vector<SurfacePtr> faces =
      test::surfaces_in_cube({kNeovius + "-0.3", "-(" + kNeovius + ")-0.3", "x*x+y*y-9", "z-3", "-3-z"}, 3.3);
  test::expect_valid_part(run, faces, test::cube_box(3.3).diagonal(), false);
}

TEST(FinerEdgeRetry, TheVertexBudgetBoundsTheRetry) {
  // The budget holds the shape at 0.4 and 0.2 but not at 0.1, where alone it meshes: refused (exact
  // creases asked), with the failure at the edge asked for.
  Settings s;
  s.box = test::cube_box(3.3);
  s.edge_length = 0.4;
  s.max_vertices = 15000;
  s.creases = Creases::Exact;
  const SurfacePtr f = expression_surface(kSheet, *s.box);
  try {
    mesh_surface(*f, s);
    ADD_FAILURE() << "meshed within a budget that a finer edge exceeds";
  } catch (const CreaseError& e) {
    EXPECT_NE(std::string(e.what()).find("closer than an edge"), std::string::npos) << e.what();
  }
}

}  // namespace finer_edge_retry_test
}  // namespace isopatch
