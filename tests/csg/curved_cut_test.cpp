// Two smooth solids intersected (csg/capped_shape.hpp CutShape, api/curved_cut.hpp): lattices cut by a
// sphere meshed as their two trimmed faces joined along the crease, whatever the faces' genus: the
// formula's split, the crease loops on both surfaces, evenly spaced and turning the right way, and the
// parts closed, manifold, outward, free of self-intersections, with the crease exact, the topology and
// volume of a finer mesh and the same bytes for any thread count.
#include <gtest/gtest.h>

#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "api/crease_loops.hpp"
#include "csg/capped_shape.hpp"
#include "mesh_checks.hpp"
#include "part_checks.hpp"

namespace isopatch {
namespace {

const std::string kCutGyroid = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)";
const std::string kCutBall = "x^2+y^2+z^2-9";

Box cut_box(double a) {
  return {Vec3::Constant(-a), Vec3::Constant(a)};
}

test::CappedRun mesh_cut(const std::string& formula, double edge, int threads = 0,
                         std::optional<Frame> frame = std::nullopt) {
  test::CappedRun run;
  run.surface = expression_surface(formula, cut_box(3.4));
  Settings s;
  s.box = cut_box(3.4);
  s.edge_length = edge;
  s.threads = threads;
  s.frame = frame;
  run.mesh = mesh_surface(*run.surface, s, &run.stats);
  return run;
}

TEST(CutShape, ALatticeCutByABallGivesBothOperandsInOrder) {
  const SurfacePtr f = expression_surface("max(" + kCutGyroid + "," + kCutBall + ")", cut_box(4.0));
  const std::optional<CutShape> shape = split_cut_shape(*f, cut_box(4.0));
  ASSERT_TRUE(shape);
  const Vec3 p(0.3, -0.7, 1.1);
  EXPECT_NEAR(shape->first->value(p),
              std::sin(0.3) * std::cos(-0.7) + std::sin(-0.7) * std::cos(1.1) + std::sin(1.1) * std::cos(0.3),
              1e-15);
  EXPECT_NEAR(shape->second->value(p), p.squaredNorm() - 9.0, 1e-14);
}

TEST(CutShape, PlanesThreeOperandsAndUnionsAreNotCutShapes) {
  for (const std::string& formula :
       {"max(" + kCutGyroid + ",z-1)", "max(max(" + kCutGyroid + "," + kCutBall + "),z-1)",
        "min(" + kCutGyroid + "," + kCutBall + ")", kCutBall}) {
    const SurfacePtr f = expression_surface(formula, cut_box(4.0));
    EXPECT_FALSE(split_cut_shape(*f, cut_box(4.0))) << formula;
  }
}

/// A smooth surface meshed in `box` at edge length `edge`.
Mesh mesh_in(const Surface& f, const Box& box, double edge) {
  Settings s;
  s.box = box;
  s.edge_length = edge;
  return mesh_surface(f, s);
}

TEST(CreaseLoops, TwoBallsMeetInOneEvenCircleOnBothTurningWithTheirGradients) {
  // |p|^2 = 1 and |p - (1, 0, 0)|^2 = 1 meet in the circle x = 1/2, radius sqrt(3)/2.
  const Box box = cut_box(2.5);
  const SurfacePtr a = expression_surface("x^2+y^2+z^2-1", box);
  const SurfacePtr b = expression_surface("(x-1)^2+y^2+z^2-1", box);
  const Mesh mesh = mesh_in(*a, box, 0.1);
  const std::vector<CreaseLoop> loops = trace_crease_loops(mesh, *a, *b, 0.1, 1e-12);
  ASSERT_EQ(loops.size(), 1u);
  const std::vector<Vec3>& p = loops[0].points;
  const double circumference = 2.0 * std::numbers::pi * std::sqrt(3.0) / 2.0;
  EXPECT_EQ(p.size(), static_cast<std::size_t>(std::lround(circumference / 0.1)));
  double shortest = INFINITY, longest = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_NEAR(p[k].x(), 0.5, 1e-11);
    EXPECT_NEAR(std::hypot(p[k].y(), p[k].z()), std::sqrt(3.0) / 2.0, 1e-11);
    const Vec3 step = p[(k + 1) % p.size()] - p[k];
    shortest = std::min(shortest, step.norm());
    longest = std::max(longest, step.norm());
    // grad a x grad b = 4 p x (p - e_x) points along the loop.
    EXPECT_GT(step.dot(p[k].cross(p[k] - Vec3(1, 0, 0))), 0.0);
  }
  EXPECT_LT(longest / shortest, 1.05);
}

TEST(CreaseLoops, ACreaseLeavingTheMeshIsRefused) {
  const Box box = cut_box(1.0);
  const SurfacePtr a = expression_surface("z", box);
  const SurfacePtr b = expression_surface("x^2+y^2-4", box);
  const Mesh plane = mesh_in(*a, box, 0.2);
  const SurfacePtr c = expression_surface("x^2+y^2-0.25", box);
  EXPECT_EQ(trace_crease_loops(plane, *a, *c, 0.2, 1e-12).size(), 1u);
  EXPECT_TRUE(trace_crease_loops(plane, *a, *b, 0.2, 1e-12).empty());
  const SurfacePtr d = expression_surface("x-0.1", box);
  EXPECT_THROW(trace_crease_loops(plane, *a, *d, 0.2, 1e-12), CreaseError);
}

std::vector<SurfacePtr> cut_faces(const std::string& lattice) {
  return {expression_surface(lattice, cut_box(3.4)), expression_surface(kCutBall, cut_box(3.4))};
}

TEST(CurvedCut, AGyroidCutByABallIsAClosedPartAlongItsCrease) {
  // The scale: an edge of 1/60 of the part's diameter.
  const test::CappedRun run = mesh_cut("max(" + kCutGyroid + "," + kCutBall + ")", 0.1);
  test::expect_valid_part(run, cut_faces(kCutGyroid), cut_box(3.4).diagonal(), false);
  EXPECT_EQ(run.stats.creases->faces, 2u);
  EXPECT_GT(run.stats.creases->creases, 0u);
}

TEST(CurvedCut, AGyroidSheetCutByABallIsAClosedPartOfTheFinerMeshsTopology) {
  // The sheet meets the ball in strips a few edges wide whose ends pinch where the two walls' creases come
  // within a fraction of an edge of each other; at 1/60 of the part (edge 0.1) the ball's face is joined
  // on a mesh of half the edge there, at 1/120 directly.
  const std::string sheet = "abs(" + kCutGyroid + ")-0.3";
  const test::CappedRun coarse = mesh_cut("max(" + sheet + "," + kCutBall + ")", 0.1);
  const test::CappedRun fine = mesh_cut("max(" + sheet + "," + kCutBall + ")", 0.05);
  for (const test::CappedRun* run : {&coarse, &fine}) {
    test::expect_valid_part(*run, cut_faces(sheet), cut_box(3.4).diagonal(), false);
    EXPECT_EQ(run->stats.creases->faces, 2u);
  }
  EXPECT_EQ(analyze_topology(coarse.mesh).genus, analyze_topology(fine.mesh).genus);
  EXPECT_EQ(analyze_topology(coarse.mesh).components.size(), analyze_topology(fine.mesh).components.size());
}

TEST(CurvedCut, TheTopologyAndVolumeOfAFinerMeshHold) {
  const std::string part = "max(" + kCutGyroid + "," + kCutBall + ")";
  const test::CappedRun coarse = mesh_cut(part, 0.1);
  const test::CappedRun fine = mesh_cut(part, 0.05);
  const TopologyReport c = analyze_topology(coarse.mesh), f = analyze_topology(fine.mesh);
  EXPECT_EQ(c.genus, f.genus);
  EXPECT_EQ(c.components.size(), f.components.size());
  // Vertices on a curved cap leave its triangles inside it: the volume falls short by about
  // h^2 / (4 R^2) of it for a ball of radius R (2.8e-4 at h = R / 30), a quarter of that at h / 2.
  const double deficit = 0.1 * 0.1 / (4.0 * 9.0);
  EXPECT_NEAR(test::enclosed_volume(coarse.mesh) / test::enclosed_volume(fine.mesh), 1.0, 1.5 * deficit);
  EXPECT_LT(test::enclosed_volume(coarse.mesh), test::enclosed_volume(fine.mesh));
}

TEST(CurvedCut, TheSameBytesForOneAndTwoThreads) {
  const std::string part = "max(" + kCutGyroid + "," + kCutBall + ")";
  const test::CappedRun one = mesh_cut(part, 0.25, 1);
  const test::CappedRun two = mesh_cut(part, 0.25, 2);
  EXPECT_EQ(one.mesh.positions, two.mesh.positions);
  EXPECT_EQ(one.mesh.triangles, two.mesh.triangles);
}

TEST(CurvedCut, ARotatedFrameKeepsTheCreaseAndTheTopology) {
  // The frame rotates each operand's partition; the crease is the shapes' own, in the world.
  const std::string part = "max(" + kCutGyroid + "," + kCutBall + ")";
  const test::CappedRun plain = mesh_cut(part, 0.1);
  const test::CappedRun turned = mesh_cut(part, 0.1, 0, Frame{30.0, 20.0, 10.0});
  test::expect_valid_part(turned, cut_faces(kCutGyroid), cut_box(3.4).diagonal(), false);
  const auto count = [](const test::CappedRun& r) {
    return static_cast<double>(r.stats.creases->crease_vertices);
  };
  EXPECT_NEAR(count(turned) / count(plain), 1.0, 0.05);
  EXPECT_EQ(analyze_topology(turned.mesh).genus, analyze_topology(plain.mesh).genus);
}

TEST(CurvedCut, ABallLeavingTheBoxIsNotTakenForACut) {
  // Neither operand's solid lies in the box: the general crease path decides (here: refused, with the
  // way out named), never an open mesh passed off as the part.
  test::CappedRun run;
  run.surface = expression_surface("max(" + kCutGyroid + ",x^2+y^2+z^2-16)", cut_box(3.0));
  Settings s;
  s.box = cut_box(3.0);
  s.edge_length = 0.25;
  try {
    run.mesh = mesh_surface(*run.surface, s, &run.stats);
    EXPECT_NE(run.stats.creases ? run.stats.creases->faces : 0u, 2u);
  } catch (const CreaseError& e) {
    EXPECT_NE(std::string(e.what()).find("creases off"), std::string::npos);
  }
}

}  // namespace
}  // namespace isopatch
