// Hard cases for both meshers (issue 8): surfaces through lattice points, tangent to or cut by the box,
// smaller or thinner than a cell, singular points, NaN regions, no crossing at all, extreme box scales,
// CSG with min/max, budgets and cancellation. Each case asserts either a valid mesh (manifold,
// consistently oriented, watertight when the surface is closed inside the box, boundary only on the box
// faces where the box cuts it) or one specific typed error with a one-line message. Never a crash.
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace isopatch {
namespace {

constexpr Method kMethods[] = {Method::Projection, Method::MarchingCubes};

Box cube(double half) {
  return Box{Vec3::Constant(-half), Vec3::Constant(half)};
}

/// Modest settings: a 24-cell grid for marching cubes, an edge length of 1/16 of the longest box
/// side for projection (so every case runs in well under a second).
Settings modest(Method method, const Box& box) {
  Settings s;
  s.method = method;
  s.box = box;
  s.grid = 24;
  s.edge_length = box.size().maxCoeff() / 16.0;
  s.max_depth = 7;
  return s;
}

double box_tolerance(const Settings& s, const Box& box);

/// The result of one run: a mesh or the typed error it threw.
struct Outcome {
  std::optional<Mesh> mesh;
  std::optional<ErrorKind> error;
  std::string message;
  MeshStats stats;
  double tolerance = 0.0;  ///< how far outside the box vertices may lie (box_tolerance)
};

Outcome run(const Surface& surface, const Settings& settings) {
  Outcome o;
  o.tolerance = box_tolerance(settings, settings.box.value_or(surface.box()));
  try {
    o.mesh = mesh_surface(surface, settings, &o.stats);
  } catch (const Error& e) {
    o.error = e.kind();
    o.message = e.what();
  }
  return o;
}

Outcome run(const std::string& formula, const Box& box, Method method,
            const std::function<void(Settings&)>& tweak = {}) {
  const SurfacePtr surface = resolve_surface(formula, box);
  Settings settings = modest(method, box);
  if (tweak) tweak(settings);
  return run(*surface, settings);
}

std::string describe(const Outcome& o) {
  if (o.mesh) return std::to_string(o.mesh->vertex_count()) + " vertices";
  return "error " + std::to_string(static_cast<int>(*o.error)) + ": " + o.message;
}

/// True when p lies on one of the faces of `box` (within `tol`).
bool on_box_face(const Vec3& p, const Box& box, double tol) {
  for (int a = 0; a < 3; ++a)
    if (std::abs(p[a] - box.lo[a]) <= tol || std::abs(p[a] - box.hi[a]) <= tol) return true;
  return false;
}

struct Expect {
  bool closed = true;          ///< watertight: the surface is closed inside the box
  std::size_t components = 0;  ///< expected connected components (0: do not check)
};

/// A valid mesh: finite positions inside the box, Mesh::validate(), manifold, consistently oriented,
/// watertight when closed, otherwise every boundary edge on a box face.
/// How far outside the box a vertex may lie: marching cubes keeps every vertex in the closed box (its
/// grid's outer planes are the box faces), projection to rounding (see VerticesStayInsideTheBox).
double box_tolerance(const Settings& s, const Box& box) {
  return s.method == Method::MarchingCubes ? 0.0 : 1e-7 * box.diagonal();
}

void expect_valid(const Outcome& o, const Box& box, const Expect& expect, double tol) {
  ASSERT_TRUE(o.mesh.has_value()) << describe(o);
  const Mesh& mesh = *o.mesh;
  ASSERT_GT(mesh.triangle_count(), 0u);
  ASSERT_NO_THROW(mesh.validate());
  for (const Vec3& p : mesh.positions) {
    ASSERT_TRUE(p.allFinite());
    ASSERT_TRUE(box.contains(p, tol)) << p.transpose();
  }
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_EQ(t.non_manifold_edges, 0u);
  EXPECT_EQ(t.non_manifold_vertices, 0u);
  EXPECT_TRUE(t.consistently_oriented()) << t.inconsistent_edges << " inconsistent edges";
  if (expect.closed) {
    EXPECT_TRUE(t.watertight()) << t.boundary_edges << " boundary edges";
    EXPECT_TRUE(t.outward_oriented());
  } else {
    EXPECT_GT(t.boundary_edges, 0u);
    // Boundary edges: edges used by exactly one triangle; both ends must lie on a box face.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const Triangle& tri : mesh.triangles)
      for (std::size_t i = 0; i < 3; ++i) {
        const auto a = tri[i], b = tri[(i + 1) % 3];
        ++uses[{std::min(a, b), std::max(a, b)}];
      }
    std::size_t off_face = 0;
    for (const auto& [edge, count] : uses)
      if (count == 1 && !(on_box_face(mesh.positions[edge.first], box, tol) &&
                          on_box_face(mesh.positions[edge.second], box, tol)))
        ++off_face;
    EXPECT_EQ(off_face, 0u) << "boundary edges away from the box faces";
  }
  if (expect.components > 0) {
    EXPECT_EQ(t.components.size(), expect.components);
  }
}

void expect_valid(const Outcome& o, const Box& box, const Expect& expect) {
  expect_valid(o, box, expect, o.tolerance);
}

void expect_error(const Outcome& o, ErrorKind kind, const std::string& part = "") {
  ASSERT_TRUE(o.error.has_value()) << "expected an error, got " << describe(o);
  EXPECT_EQ(*o.error, kind) << o.message;
  EXPECT_EQ(o.message.find('\n'), std::string::npos) << o.message;
  EXPECT_FALSE(o.message.empty());
  if (!part.empty()) {
    EXPECT_NE(o.message.find(part), std::string::npos) << o.message;
  }
}

#define FOR_EACH_METHOD                \
  for (const Method method : kMethods) \
    if (SCOPED_TRACE(method_name(method)); true)

// ---- Surfaces through lattice points --------------------------------------------------------------

TEST(HardCases, SphereThroughLatticePoints) {
  // Radius 0.5 in [-1,1]^3: every dyadic lattice (and the marching cubes grid without its offset)
  // has points exactly on the sphere, e.g. (0.5, 0, 0).
  FOR_EACH_METHOD {
    expect_valid(run("x^2+y^2+z^2-0.25", cube(1), method), cube(1), {true, 1});
    expect_valid(run("x^2+y^2+z^2-0.25", cube(1), method, [](Settings& s) { s.grid_offset = 0.0; }), cube(1),
                 {true, 1});
  }
}

TEST(HardCases, PlaneThroughLatticePoints) {
  // x = 0 exactly: a whole lattice plane where f is zero; the box cuts the plane open.
  FOR_EACH_METHOD {
    expect_valid(run("x", cube(1), method), cube(1), {false, 1});
    expect_valid(run("x", cube(1), method, [](Settings& s) { s.grid_offset = 0.0; }), cube(1), {false, 1});
  }
}

// ---- The box --------------------------------------------------------------------------------------

TEST(HardCases, SphereTangentToBoxFaces) {
  // Radius 1 in [-1,1]x[-2,2]x[-2,2]: the sphere touches the faces x = -1 and x = 1 at one point each.
  const Box box{Vec3(-1, -2, -2), Vec3(1, 2, 2)};
  FOR_EACH_METHOD {
    const Outcome o = run("x^2+y^2+z^2-1", box, method);
    // Either closed, or open only at the tangent points (tiny holes on the faces x = +-1).
    ASSERT_TRUE(o.mesh.has_value()) << describe(o);
    const TopologyReport t = analyze_topology(*o.mesh);
    expect_valid(o, box, {t.boundary_edges == 0, 1});
  }
}

TEST(HardCases, SurfaceCutOpenByTheBox) {
  // A sphere of radius 0.85 in [-0.7,0.7]^3: the box faces (at 0.7) cut off six caps, the box edges
  // (at 0.99) do not touch it: one component with six holes.
  // A torus cut in half by z = 0.
  FOR_EACH_METHOD {
    expect_valid(run("x^2+y^2+z^2-0.7225", cube(0.7), method), cube(0.7), {false, 1});
    const Box half{Vec3(-1.6, -1.6, 0.0), Vec3(1.6, 1.6, 3.2)};
    expect_valid(run("(x^2+y^2+z^2+1-0.16)^2-4*(x^2+y^2)", half, method), half, {false, 1});
  }
}

// ---- Features smaller than a cell -----------------------------------------------------------------

TEST(HardCases, ComponentSmallerThanACell) {
  // A unit sphere plus a sphere of radius 0.01 at (1.5, 1.5, 1.5), in [-2,2]^3 (cells of 1/6 and 1/4).
  // Neither mesher promises to find it: the run succeeds with the big sphere, and the tiny one is
  // either missing or meshed as a closed component of its own. Now: projection misses it (1 component),
  // marching cubes finds it (2 components). Alone in [-1,1]^3 (next test) it is the other way round:
  // projection meshes it (18 vertices), marching cubes throws NoSurfaceError.
  const std::string formula = "min(x^2+y^2+z^2-1, (x-1.5)^2+(y-1.5)^2+(z-1.5)^2-0.0001)";
  FOR_EACH_METHOD {
    const Outcome o = run(formula, cube(2), method);
    expect_valid(o, cube(2), {true, 0});
    ASSERT_TRUE(o.mesh.has_value());
    const auto components = analyze_topology(*o.mesh).components.size();
    EXPECT_TRUE(components == 1 || components == 2) << components;
    RecordProperty(method_name(method) + "_components", static_cast<int>(components));
  }
}

TEST(HardCases, ComponentSmallerThanACellAlone) {
  // Only the tiny sphere (radius 0.01 in [-1,1]^3, off-centre so no lattice point is inside):
  // either a closed mesh of it or NoSurfaceError, never anything else (see above for which is which).
  const std::string formula = "(x-0.3)^2+(y-0.3)^2+(z-0.3)^2-0.0001";
  FOR_EACH_METHOD {
    const Outcome o = run(formula, cube(1), method);
    if (o.mesh)
      expect_valid(o, cube(1), {true, 1});
    else
      expect_error(o, ErrorKind::NoSurface, "no surface in the box");
  }
}

TEST(HardCases, SheetThinnerThanACell) {
  // A slab |x| < 0.01 (two parallel planes 0.02 apart, cells of 1/12 and 1/8): f = |x| - 0.01 is
  // negative only between grid planes. A valid (non-empty) mesh or NoSurfaceError. Now: marching cubes
  // throws NoSurfaceError; projection meshes both planes (2 components, refined down to the slab).
  FOR_EACH_METHOD {
    const Outcome o = run("abs(x-0.013)-0.01", cube(1), method);
    if (o.mesh) {
      expect_valid(o, cube(1), {false, 0});
    } else {
      expect_error(o, ErrorKind::NoSurface, "no surface in the box");
    }
  }
}

TEST(HardCases, TwoSheetsCloserThanACell) {
  // Concentric spheres of radius 0.5 and 0.52 (a shell 0.02 thick; cells of 1/12 and 1/8).
  // Projection: cells holding two sheets are split down to max_depth (not closed by fans at the patch
  // refinement limit), so the mesh is the two spheres, each oriented along grad f (the inner one faces
  // the centre, into the cavity). Marching cubes, the baseline, cannot see sheets closer than its grid
  // and meshes a closed manifold of the wrong topology at this grid: asserted only as valid.
  const std::string formula = "(x^2+y^2+z^2-0.25)*(x^2+y^2+z^2-0.2704)";
  const Outcome p = run(formula, cube(1), Method::Projection);
  ASSERT_TRUE(p.mesh.has_value()) << describe(p);
  const TopologyReport t = analyze_topology(*p.mesh);
  EXPECT_TRUE(t.watertight() && t.manifold() && t.consistently_oriented());
  EXPECT_EQ(t.components.size(), 2u);
  EXPECT_EQ(t.genus, 0);
  const Outcome m = run(formula, cube(1), Method::MarchingCubes);
  ASSERT_TRUE(m.mesh.has_value()) << describe(m);
  const TopologyReport tm = analyze_topology(*m.mesh);
  EXPECT_TRUE(tm.watertight() && tm.manifold() && tm.consistently_oriented());
}

// ---- Singular points ------------------------------------------------------------------------------

/// A mesh that is at least structurally sound (finite, valid indices, inside the box) or an
/// EvaluationError: the contract for surfaces with singular points.
void expect_sound_or_evaluation_error(const Outcome& o, const Box& box) {
  if (!o.mesh) {
    expect_error(o, ErrorKind::Evaluation);
    return;
  }
  ASSERT_NO_THROW(o.mesh->validate());
  for (const Vec3& p : o.mesh->positions) {
    ASSERT_TRUE(p.allFinite());
    ASSERT_TRUE(box.contains(p, o.tolerance)) << p.transpose();
  }
  EXPECT_NO_THROW(analyze_topology(*o.mesh));
}

TEST(HardCases, HeartWithSingularPoints) {
  const SurfacePtr heart = catalogue_surface("heart");
  FOR_EACH_METHOD {
    Settings s = modest(method, heart->box());
    expect_sound_or_evaluation_error(run(*heart, s), heart->box());
  }
}

TEST(HardCases, ConeApex) {
  // x^2 + y^2 - z^2: the apex at the origin (grad f = 0 on the surface), which is also a lattice point.
  FOR_EACH_METHOD {
    expect_sound_or_evaluation_error(run("x^2+y^2-z^2", cube(1), method), cube(1));
    const Box shifted{Vec3(-0.9, -1.1, -1.0), Vec3(1.1, 0.9, 1.0)};
    expect_sound_or_evaluation_error(run("x^2+y^2-z^2", shifted, method), shifted);
  }
}

// ---- NaN and infinity -----------------------------------------------------------------------------

TEST(HardCases, NanInPartOfTheBoxNamesThePoint) {
  // sqrt(x) and log(x) are NaN (or -inf) for x < 0, which is half the box.
  for (const char* formula : {"sqrt(x)+y^2+z^2-0.5", "log(x+0.5)+y^2+z^2-0.5", "log(x)+y^2+z^2"}) {
    SCOPED_TRACE(formula);
    FOR_EACH_METHOD {
      const Outcome o = run(formula, cube(1), method);
      expect_error(o, ErrorKind::Evaluation);
      // The message names the point: "... at (x, y, z)".
      EXPECT_NE(o.message.find(" at ("), std::string::npos) << o.message;
    }
  }
}

// ---- No surface -----------------------------------------------------------------------------------

TEST(HardCases, NoCrossingAtAll) {
  FOR_EACH_METHOD {
    // Everything inside, everything outside, a sphere entirely outside the box.
    for (const char* formula : {"x^2+y^2+z^2-100", "x^2+y^2+z^2+1", "(x-5)^2+y^2+z^2-1"}) {
      SCOPED_TRACE(formula);
      expect_error(run(formula, cube(1), method), ErrorKind::NoSurface, "no surface in the box");
    }
  }
}

TEST(HardCases, ConstantFunctions) {
  // f = 1 and f = -1: nothing crosses. f = 0: every point is on the "surface", which has no
  // orientation and no mesh: NoSurfaceError too, saying that f is identically zero.
  FOR_EACH_METHOD {
    for (const char* formula : {"1", "-1", "0", "x-x", "0*x"}) {
      SCOPED_TRACE(formula);
      expect_error(run(formula, cube(1), method), ErrorKind::NoSurface, "no surface in the box");
    }
  }
}

TEST(HardCases, ZeroFunctionGivesUpQuickly) {
  // f = 0 defeats interval pruning ([0, 0] contains 0) and has no sign change: projection used to
  // subdivide the whole octree to max_depth (15-25 s at the default depth 8) before giving up.
  // mesh_surface now rejects it up front, for both methods, at the default settings.
  for (const char* formula : {"0", "x-x", "0*x", "0*sin(x*y)+z-z"}) {
    SCOPED_TRACE(formula);
    FOR_EACH_METHOD {
      Settings settings;
      settings.method = method;
      const SurfacePtr surface = resolve_surface(formula, cube(1));
      const auto start = std::chrono::steady_clock::now();
      const Outcome o = run(*surface, settings);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      expect_error(o, ErrorKind::NoSurface, "f is identically zero");
      EXPECT_LT(seconds, 5.0);  // generous (sanitizers, loaded machine): catches the old subdivision
    }
  }
}

// ---- Scale ----------------------------------------------------------------------------------------

TEST(HardCases, TinyAndHugeBoxes) {
  for (const double scale : {1e-6, 1e6}) {
    SCOPED_TRACE(scale);
    char s[64];
    std::snprintf(s, sizeof s, "%.17g", scale);
    const std::string formula = std::string("s = ") + s + "; (x/s)^2+(y/s)^2+(z/s)^2-0.64";
    FOR_EACH_METHOD {
      const Box box = cube(scale);
      const Outcome o = run(formula, box, method);
      expect_valid(o, box, {true, 1});
      if (o.mesh) {
        // The vertices are near the sphere of radius 0.8 * scale.
        for (const Vec3& p : o.mesh->positions) EXPECT_NEAR(p.norm() / scale, 0.8, 0.05);
      }
    }
  }
}

// ---- CSG ------------------------------------------------------------------------------------------

TEST(HardCases, UnionOfTwoSpheresViaMin) {
  // Two overlapping spheres: a crease circle where grad f jumps. A closed mesh, possibly with fallback
  // cells along the crease.
  const std::string formula = "min((x-0.4)^2+y^2+z^2-0.36, (x+0.4)^2+y^2+z^2-0.36)";
  FOR_EACH_METHOD {
    const Outcome o = run(formula, cube(1.2), method);
    expect_valid(o, cube(1.2), {true, 1});
    if (o.mesh) {
      EXPECT_EQ(analyze_topology(*o.mesh).genus, 0);
    }
  }
}

TEST(HardCases, IntersectionAndDifferenceViaMax) {
  // Lens (intersection) and a sphere with a bite taken out (difference): sharp creases.
  const std::string lens = "max((x-0.3)^2+y^2+z^2-0.49, (x+0.3)^2+y^2+z^2-0.49)";
  const std::string bite = "max(x^2+y^2+z^2-0.64, 0.16-(x-0.6)^2-y^2-z^2)";
  FOR_EACH_METHOD {
    expect_valid(run(lens, cube(1), method), cube(1), {true, 1});
    expect_valid(run(bite, cube(1), method), cube(1), {true, 1});
  }
}

// ---- Budgets and cancellation ---------------------------------------------------------------------

TEST(HardCases, MaxVerticesCap) {
  FOR_EACH_METHOD {
    const Outcome o = run("x^2+y^2+z^2-0.64", cube(1), method, [](Settings& s) { s.max_vertices = 10; });
    expect_error(o, ErrorKind::Limit, "10");
  }
}

TEST(HardCases, CancelFlagSetBeforeTheRun) {
  static std::atomic<bool> cancel{true};
  FOR_EACH_METHOD {
    const Outcome o = run("x^2+y^2+z^2-0.64", cube(1), method, [](Settings& s) { s.cancel = &cancel; });
    expect_error(o, ErrorKind::Limit, "cancel");
  }
}

TEST(HardCases, CancelFlagRaisedFromProgress) {
  // Raised during the run (from the progress callback, as a UI thread would): LimitError, not a
  // partial mesh.
  FOR_EACH_METHOD {
    std::atomic<bool> cancel{false};
    const Outcome o = run("x^2+y^2+z^2-0.64", cube(1), method, [&](Settings& s) {
      s.cancel = &cancel;
      s.progress = [&](const Progress&) { cancel = true; };
    });
    expect_error(o, ErrorKind::Limit, "cancel");
  }
}

// ---- The box limits evaluation and output --------------------------------------------------------

/// A surface cut by the box, for the inside-the-box tests.
struct CutCase {
  std::string formula;
  Box box;
  std::size_t components;
};

std::vector<CutCase> cut_cases() {
  // The unit sphere in [-0.7,0.7]^3 leaves eight pieces, one around each box corner (a point of the
  // sphere with a zero coordinate would need 0.7^2 + 0.7^2 >= 1).
  const Box half{Vec3(-1.6, -1.6, 0.0), Vec3(1.6, 1.6, 0.6)};
  return {
      {"x", cube(1), 1}, {"x^2+y^2+z^2-1", cube(0.7), 8}, {"(x^2+y^2+z^2+1-0.16)^2-4*(x^2+y^2)", half, 1}};
}

/// Functions finite on the closed box [-1,1]^3 but NaN just beyond it. (log(x+1), which an earlier
/// version listed, is -inf on the face x = -1 itself: an EvaluationError wherever the face is sampled.)
const char* const kDefinedOnlyInTheBox[] = {"sqrt(x+1)+y^2+z^2-1", "x^2+y^2+z^2-0.25+0*sqrt(1-x)",
                                            "sqrt(x+1)-0.5"};

TEST(HardCases, VerticesStayInsideTheBox) {
  // Marching cubes: the grid's outer planes are the box faces (it used to overhang the hi faces by up to
  // a cell). Projection used to put vertices up to two edge lengths outside (boundary rays leaving the
  // faces; for a box that is not a cube, the root cell is the box made cubic).
  for (const CutCase& c : cut_cases()) {
    SCOPED_TRACE(c.formula);
    FOR_EACH_METHOD {
      const Outcome o = run(c.formula, c.box, method);
      expect_valid(o, c.box, {false, c.components});
    }
  }
}

TEST(HardCases, MarchingCubesEvaluatesOnlyInsideTheBox) {
  for (const char* formula : kDefinedOnlyInTheBox) {
    SCOPED_TRACE(formula);
    const Outcome o = run(formula, cube(1), Method::MarchingCubes);
    EXPECT_TRUE(o.mesh.has_value()) << describe(o);
  }
}

// ---- Evaluation only inside the box --------------------------------------------------------------

TEST(HardCases, ProjectionEvaluatesOnlyInsideTheBox) {
  // f defined on the whole closed box [-1,1]^3 but not beyond it. The octree's lattice overhangs the box
  // (2% and a non-dyadic shift); its positions are clamped into the box, so f is evaluated only there.
  // sqrt(x+1)+y^2+z^2-1 meets the face x = -1, where its gradient is infinite: projection needs the
  // gradient at its corners, so it reports that, at a point of the face (not beyond it).
  for (const char* formula : kDefinedOnlyInTheBox) {
    SCOPED_TRACE(formula);
    const Outcome o = run(formula, cube(1), Method::Projection);
    if (std::string(formula) == "sqrt(x+1)+y^2+z^2-1") {
      ASSERT_EQ(o.error, ErrorKind::Evaluation) << describe(o);
      EXPECT_NE(o.message.find("grad f is infinite at (-1,"), std::string::npos) << o.message;
    } else {
      EXPECT_TRUE(o.mesh.has_value()) << describe(o);
    }
  }
}

}  // namespace
}  // namespace isopatch
