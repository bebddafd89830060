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
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/box_boundary_loops.hpp"
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

/// The vertices of `mesh` on its boundary edges.
std::vector<std::uint32_t> boundary_of(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (const Triangle& t : mesh.triangles)
    for (std::size_t k = 0; k < 3; ++k) ++count[std::minmax(t[k], t[(k + 1) % 3])];
  std::vector<std::uint32_t> out;
  for (const auto& [e, n] : count)
    if (n == 1) out.insert(out.end(), {e.first, e.second});
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
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

TEST(CutShape, PlanesAndOneOperandAreNotCutShapes) {
  // (Unions of two solids are: united_cut_test.cpp.)
  for (const std::string& formula :
       {"max(" + kCutGyroid + ",z-1)", "max(max(" + kCutGyroid + "," + kCutBall + "),z-1)", kCutBall}) {
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

TEST(CreaseLoops, ACreaseLeavingTheMeshIsRefusedUnlessTheBoxCutsIt) {
  const Box box = cut_box(1.0);
  const SurfacePtr a = expression_surface("z", box);
  const SurfacePtr b = expression_surface("x^2+y^2-4", box);
  const Mesh plane = mesh_in(*a, box, 0.2);
  const SurfacePtr c = expression_surface("x^2+y^2-0.25", box);
  EXPECT_EQ(trace_crease_loops(plane, *a, *c, 0.2, 1e-12).size(), 1u);
  EXPECT_TRUE(trace_crease_loops(plane, *a, *b, 0.2, 1e-12).empty());
  const SurfacePtr d = expression_surface("x-0.1", box);
  EXPECT_THROW(trace_crease_loops(plane, *a, *d, 0.2, 1e-12), CreaseError);
  // Cut by the box: one arc from y = -1 to y = 1 (grad a x grad b = +y), its ends exactly on those faces.
  const std::vector<CreaseLoop> arcs = trace_crease_loops(plane, *a, *d, 0.2, 1e-12, &box);
  ASSERT_EQ(arcs.size(), 1u);
  const std::vector<Vec3>& p = arcs[0].points;
  EXPECT_FALSE(arcs[0].closed);
  ASSERT_EQ(p.size(), 11u);
  EXPECT_EQ(p.front().y(), -1.0);
  EXPECT_EQ(p.back().y(), 1.0);
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_NEAR(p[k].x(), 0.1, 1e-12);
    EXPECT_NEAR(p[k].z(), 0.0, 1e-12);
    EXPECT_NEAR(p[k].y(), -1.0 + 0.2 * static_cast<double>(k), 1e-9);
  }
}

TEST(BoxBoundaryLoops, AnArcAndTheMeshsBoundaryInsideTheOtherSolidCloseOneLoop) {
  // The plane z = 0 in [-1, 1]^3 where x < 0.1: bounded by the crease's arc x = 0.1 (from y = -1 to 1, the
  // face on its left) and the square's sides where x < 0.1, in one loop with the face on its left.
  const Box box = cut_box(1.0);
  const SurfacePtr a = expression_surface("z", box);
  const SurfacePtr b = expression_surface("x-0.1", box);
  const Mesh plane = mesh_in(*a, box, 0.2);
  const std::vector<CreaseLoop> arcs = trace_crease_loops(plane, *a, *b, 0.2, 1e-12, &box);
  ASSERT_EQ(arcs.size(), 1u);
  std::vector<std::uint8_t> inside(plane.positions.size(), 0);
  std::size_t boundary_inside = 0;
  const std::vector<std::uint32_t> boundary = boundary_of(plane);
  for (std::size_t v = 0; v < inside.size(); ++v) inside[v] = plane.positions[v].x() < 0.1 ? 1 : 0;
  for (std::uint32_t v : boundary) boundary_inside += inside[v];
  const std::vector<std::vector<BoundaryPoint>> loops =
      box_boundary_loops(plane, inside, {arcs[0].points}, 0.2);
  ASSERT_EQ(loops.size(), 1u);
  const std::vector<BoundaryPoint>& loop = loops[0];
  ASSERT_EQ(loop.size(), arcs[0].points.size() + boundary_inside);
  for (std::size_t k = 0; k < arcs[0].points.size(); ++k) {
    EXPECT_EQ(loop[k].arc, 0);
    EXPECT_EQ(loop[k].index, k);
  }
  // Then around the square from (0.1, 1) to (0.1, -1) through x = -1: the face on the left of each step.
  Vec3 previous = arcs[0].points.back();
  double turning = 0.0;
  for (std::size_t k = arcs[0].points.size(); k < loop.size(); ++k) {
    ASSERT_EQ(loop[k].arc, -1);
    const Vec3& p = plane.positions[loop[k].index];
    EXPECT_LT(p.x(), 0.1);
    EXPECT_EQ(std::max(std::abs(p.x()), std::abs(p.y())), 1.0);
    turning += previous.x() * p.y() - previous.y() * p.x();
    previous = p;
  }
  EXPECT_GT(turning, 0.0);  // counter-clockwise about +z, the face's normal
  // An arc end with no crossing near it is refused.
  std::vector<std::uint8_t> none(plane.positions.size(), 1);
  EXPECT_THROW(box_boundary_loops(plane, none, {arcs[0].points}, 0.2), CreaseError);
}

TEST(CreaseLoops, AnArcEndsOnTheTwoFacesOfTheBoxItCrosses) {
  // The crease x + y = 1.5, z = 0 crosses the corner of the box from the face y = 1 to the face x = 1,
  // along grad a x grad b = (-1, 1, 0).
  const Box box = cut_box(1.0);
  const SurfacePtr a = expression_surface("z", box);
  const SurfacePtr d = expression_surface("x+y-1.5", box);
  const Mesh plane = mesh_in(*a, box, 0.2);
  const std::vector<CreaseLoop> arcs = trace_crease_loops(plane, *a, *d, 0.2, 1e-12, &box);
  ASSERT_EQ(arcs.size(), 1u);
  EXPECT_EQ(arcs[0].points.front().x(), 1.0);
  EXPECT_NEAR(arcs[0].points.front().y(), 0.5, 1e-12);
  EXPECT_NEAR(arcs[0].points.back().x(), 0.5, 1e-12);
  EXPECT_EQ(arcs[0].points.back().y(), 1.0);
  EXPECT_GE(arcs[0].points.size(), 4u);
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

/// The gyroid inside a ball of radius^2 `r2` that the box [-3, 3]^3 cuts.
test::CappedRun mesh_open_cut(double edge, const std::string& r2 = "16", int threads = 0) {
  test::CappedRun run;
  const std::string part = "max(" + kCutGyroid + ",x^2+y^2+z^2-" + r2 + ")";
  run.surface = expression_surface(part, cut_box(3.0));
  Settings s;
  s.box = cut_box(3.0);
  s.edge_length = edge;
  s.threads = threads;
  run.mesh = mesh_surface(*run.surface, s, &run.stats);
  return run;
}

TEST(CurvedCut, ABallLeavingTheBoxCutsThePartOpenAlongItsCrease) {
  // Neither solid lies in the box: the box cuts the part open. Its boundary lies exactly on the box's
  // faces, the crease runs in arcs from the box to the box, every crease vertex on both surfaces.
  const test::CappedRun run = mesh_open_cut(0.15);
  const Box box = cut_box(3.0);
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_FALSE(t.watertight());
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_EQ(t.unreferenced_vertices, 0u);
  EXPECT_EQ(test::count_self_intersections(run.mesh, 10), 0u);
  ASSERT_TRUE(run.stats.creases);
  EXPECT_EQ(run.stats.creases->faces, 2u);
  EXPECT_GT(run.stats.creases->creases, 0u);
  const std::vector<std::uint32_t> boundary = boundary_of(run.mesh);
  ASSERT_FALSE(boundary.empty());
  for (std::uint32_t v : boundary) {
    const Vec3& p = run.mesh.positions[v];
    EXPECT_LT(std::min((p - box.lo).cwiseAbs().minCoeff(), (p - box.hi).cwiseAbs().minCoeff()), 1e-12)
        << p.transpose();
  }
  const SurfacePtr gyroid = expression_surface(kCutGyroid, box);
  const SurfacePtr ball = expression_surface("x^2+y^2+z^2-16", box);
  std::size_t crease = 0, crease_on_box = 0;
  for (const Vec3& p : run.mesh.positions) {
    const double on_gyroid = std::abs(gyroid->value(p)) / gyroid->value_gradient(p).gradient.norm();
    const double on_ball = std::abs(ball->value(p)) / ball->value_gradient(p).gradient.norm();
    EXPECT_LT(std::min(on_gyroid, on_ball), 1e-9 * box.diagonal());
    if (on_gyroid < 1e-9 * box.diagonal() && on_ball < 1e-9 * box.diagonal()) {
      ++crease;
      if (std::min((p - box.lo).cwiseAbs().minCoeff(), (p - box.hi).cwiseAbs().minCoeff()) == 0.0)
        ++crease_on_box;
    }
  }
  EXPECT_GE(run.stats.creases->crease_vertices, crease);
  EXPECT_GT(crease, 0u);
  // Every arc's two ends lie exactly on the box.
  EXPECT_GE(crease_on_box, 2u);
  EXPECT_EQ(crease_on_box % 2, 0u);
  const std::vector<int> valence = test::valences(run.mesh);
  std::size_t interior_six = 0, interior = 0;
  const std::vector<std::uint32_t>& b = boundary;
  for (std::uint32_t v = 0; v < valence.size(); ++v)
    if (!std::binary_search(b.begin(), b.end(), v)) {
      ++interior;
      interior_six += valence[v] == 6 ? 1 : 0;
    }
  EXPECT_GE(static_cast<double>(interior_six) / static_cast<double>(interior), 0.85);
}

TEST(CurvedCut, ThePartCutOpenByTheBoxHasTheTopologyOfAFinerMesh) {
  const test::CappedRun coarse = mesh_open_cut(0.2, "12.25");
  const test::CappedRun fine = mesh_open_cut(0.1, "12.25");
  const TopologyReport c = analyze_topology(coarse.mesh), f = analyze_topology(fine.mesh);
  ASSERT_TRUE(coarse.stats.creases && fine.stats.creases);
  EXPECT_EQ(coarse.stats.creases->creases, fine.stats.creases->creases);
  EXPECT_EQ(c.euler_characteristic, f.euler_characteristic);
  EXPECT_EQ(c.components.size(), f.components.size());
  const auto loops = [](const TopologyReport& r) {
    std::size_t n = 0;
    for (const ComponentTopology& k : r.components) n += k.boundary_loops;
    return n;
  };
  EXPECT_EQ(loops(c), loops(f));
}

TEST(CurvedCut, ThePartCutOpenByTheBoxIsTheSameBytesForOneAndTwoThreads) {
  const test::CappedRun one = mesh_open_cut(0.2, "12.25", 1);
  const test::CappedRun two = mesh_open_cut(0.2, "12.25", 2);
  ASSERT_TRUE(one.stats.creases);
  EXPECT_EQ(one.mesh.positions, two.mesh.positions);
  EXPECT_EQ(one.mesh.triangles, two.mesh.triangles);
}

TEST(CurvedCut, AJoinThatFailsIsTheReasonNotAShapeFault) {
  // A gyroid of period 1.1 in the unit ball at edge 0.1 (random model 1912): its surfaces nearly touch
  // the ball in features narrower than an edge and the join fails even on meshes of half the edge. Two
  // smooth solids are a 2-manifold unless they meet tangentially, so the general path's "not a
  // 2-manifold" (its own failure to cut the gyroid's face) is not the verdict: Creases::Exact refuses
  // the shape with the join's reason, and by default it is meshed smooth with that reason in its warnings
  // (docs/creases.md), not refused as a shape fault.
  const std::string part =
      "max(sin(5.702*x)*cos(5.702*y)+sin(5.702*y)*cos(5.702*z)+sin(5.702*z)*cos(5.702*x),x^2+y^2+z^2-1)";
  const Box box{Vec3(-1.579, -1.627, -1.518), Vec3(1.653, 1.626, 1.688)};
  const SurfacePtr f = expression_surface(part, box);
  Settings s;
  s.box = box;
  s.edge_length = 0.1;
  s.creases = Creases::Exact;
  try {
    mesh_surface(*f, s);
    ADD_FAILURE() << "no CreaseError with Creases::Exact";
  } catch (const ShapeNotManifoldError& e) {
    ADD_FAILURE() << "two smooth solids are no shape fault: " << e.what();
  } catch (const CreaseError& e) {
    EXPECT_NE(std::string(e.what()).find("two solids"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace isopatch
