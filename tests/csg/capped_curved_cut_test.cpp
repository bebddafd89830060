// Two smooth solids capped by axis-aligned planes (csg/capped_shape.hpp CappedCutShape,
// api/capped_curved_cut.hpp): a lattice in a cylinder capped at both ends, a lattice in a ball cut flat.
// The formula's split in any grouping, and the parts closed, manifold, outward, free of
// self-intersections, with every crease vertex on both of its faces, caps on the planes, the topology
// and volume of a finer mesh and the same bytes for any thread count.
#include <gtest/gtest.h>

#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "csg/capped_shape.hpp"
#include "mesh_checks.hpp"
#include "part_checks.hpp"

namespace isopatch {
namespace {

const std::string kGyroid = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)";
const std::string kDiamond = "cos(x)*cos(y)*cos(z)-sin(x)*sin(y)*sin(z)";
const std::string kCylinder = "x^2+y^2-25";

Box part_box() {
  return {Vec3::Constant(-6.6), Vec3::Constant(6.6)};
}

test::CappedRun mesh_part(const std::string& formula, double edge, int threads = 0) {
  test::CappedRun run;
  run.surface = expression_surface(formula, part_box());
  Settings s;
  s.box = part_box();
  s.edge_length = edge;
  s.threads = threads;
  run.mesh = mesh_surface(*run.surface, s, &run.stats);
  return run;
}

std::vector<SurfacePtr> faces_of(const std::vector<std::string>& formulas) {
  std::vector<SurfacePtr> out;
  for (const std::string& f : formulas) out.push_back(expression_surface(f, part_box()));
  return out;
}

TEST(CappedCutShape, TwoCurvedOperandsAndPlanesInAnyGrouping) {
  for (const std::string& formula : {"max(" + kGyroid + ",max(" + kCylinder + ",abs(z)-5))",
                                     "max(max(" + kGyroid + "," + kCylinder + "),abs(z)-5)",
                                     "max(" + kGyroid + "," + kCylinder + ",z-5,-5-z)"}) {
    const SurfacePtr f = expression_surface(formula, part_box());
    const std::optional<CappedCutShape> shape = split_capped_cut_shape(*f, part_box());
    ASSERT_TRUE(shape) << formula;
    EXPECT_EQ(shape->planes.size(), 2u) << formula;
    EXPECT_NEAR(shape->solids.second->value(Vec3(5, 0, 1)), 0.0, 1e-12);
  }
  // One curved operand (a capped solid), no plane (a curved cut), a union: not this form.
  for (const std::string& formula :
       {"max(" + kGyroid + ",abs(z)-5)", "max(" + kGyroid + "," + kCylinder + ")",
        "min(max(" + kGyroid + "," + kCylinder + "),abs(z)-5)"}) {
    const SurfacePtr f = expression_surface(formula, part_box());
    EXPECT_FALSE(split_capped_cut_shape(*f, part_box())) << formula;
  }
}

TEST(CappedCurvedCut, ADiamondLatticeInACappedCylinderIsOneClosedPart) {
  const test::CappedRun run = mesh_part("max(" + kDiamond + "," + kCylinder + ",abs(z)-5)", 0.2);
  test::expect_valid_part(run, faces_of({kDiamond, kCylinder, "z-5", "-z-5"}), part_box().diagonal());
  EXPECT_EQ(run.stats.creases->caps, 2u);
  EXPECT_EQ(run.stats.creases->faces, 4u);
}

TEST(CappedCurvedCut, AGyroidInABallCutFlatIsOneClosedPart) {
  const test::CappedRun run = mesh_part("max(" + kGyroid + ",x^2+y^2+z^2-36,z-3)", 0.2);
  test::expect_valid_part(run, faces_of({kGyroid, "x^2+y^2+z^2-36", "z-3"}), part_box().diagonal());
  EXPECT_EQ(run.stats.creases->caps, 1u);
}

TEST(CappedCurvedCut, TheGyroidInACappedCylinderHasTheTopologyAndVolumeOfAFinerMesh) {
  // The gyroid is odd and the capped cylinder symmetric about the origin: the solid is half the cylinder.
  const std::string part = "max(" + kGyroid + "," + kCylinder + ",abs(z)-5)";
  const test::CappedRun coarse = mesh_part(part, 0.2);
  const test::CappedRun fine = mesh_part(part, 0.1);
  for (const test::CappedRun* run : {&coarse, &fine}) {
    const TopologyReport t = analyze_topology(run->mesh);
    EXPECT_TRUE(t.watertight());
    EXPECT_TRUE(t.manifold());
    EXPECT_TRUE(t.consistently_oriented());
    EXPECT_EQ(test::count_self_intersections(run->mesh, 10), 0u);
    ASSERT_TRUE(run->stats.creases);
    EXPECT_EQ(run->stats.creases->caps, 2u);
    EXPECT_LT(test::max_vertex_distance(*run->surface, run->mesh), 1e-9 * part_box().diagonal());
  }
  EXPECT_EQ(analyze_topology(coarse.mesh).genus, analyze_topology(fine.mesh).genus);
  EXPECT_EQ(analyze_topology(coarse.mesh).components.size(), analyze_topology(fine.mesh).components.size());
  const double half = 0.5 * std::numbers::pi * 25.0 * 10.0;
  // Curved faces lose about h^2 / (4 R^2) of the volume (vertices on the surface, triangles inside it).
  EXPECT_NEAR(test::enclosed_volume(coarse.mesh) / half, 1.0, 2e-3);
  EXPECT_NEAR(test::enclosed_volume(fine.mesh) / half, 1.0, 5e-4);
}

TEST(CappedCurvedCut, TheSameBytesForOneAndTwoThreads) {
  const std::string part = "max(" + kGyroid + "," + kCylinder + ",abs(z)-5)";
  const test::CappedRun one = mesh_part(part, 0.3, 1);
  const test::CappedRun two = mesh_part(part, 0.3, 2);
  EXPECT_EQ(one.mesh.positions, two.mesh.positions);
  EXPECT_EQ(one.mesh.triangles, two.mesh.triangles);
}

}  // namespace
}  // namespace isopatch
