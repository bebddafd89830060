// f identically zero (issue 8): rejected up front by mesh_surface with a one-line NoSurfaceError for
// both methods, from the interval bound or from samples of f and grad f; never for a legitimate surface
// that happens to vanish at some samples, or on part of the box.
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <string>

#include "surface/zero_function.hpp"

namespace isopatch {
namespace {

const Box kCube{Vec3::Constant(-1), Vec3::Constant(1)};

ZeroEvidence evidence(const std::string& formula, const Box& box = kCube) {
  return zero_function_evidence(*resolve_surface(formula, box), box);
}

TEST(ZeroFunction, FoundByTheIntervalBoundOrBySamples) {
  EXPECT_EQ(evidence("0"), ZeroEvidence::Interval);
  // Formulas whose interval bound is wider than [0, 0] (dependency, rounding) are caught by the samples.
  for (const char* formula : {"x-x", "0*x", "sin(x)^2*0", "(x+y)-(y+x)"}) {
    SCOPED_TRACE(formula);
    EXPECT_EQ(evidence(formula), ZeroEvidence::Samples);
  }
  const SurfacePtr callable = make_surface([](auto x, auto y, auto z) { return 0.0 * x * y * z; }, kCube);
  EXPECT_EQ(zero_function_evidence(*callable, kCube), ZeroEvidence::Samples);  // a callable has no bound
}

TEST(ZeroFunction, NotFoundForSurfacesThatVanishOnlyInPlaces) {
  // Zero at some samples or on lattice planes, grad f nonzero there.
  for (const char* formula : {"x", "x*y*z", "x^2+y^2+z^2-0.25", "x^3", "sin(8*pi*x)"}) {
    SCOPED_TRACE(formula);
    EXPECT_EQ(evidence(formula), ZeroEvidence::None);
  }
  // f and grad f exactly zero on most of the box (x < 0.75, where max(...) = 0), a sign change in the rest:
  // the samples with x > 0.75 decide.
  EXPECT_EQ(evidence("max(x-0.75,0)^2*y"), ZeroEvidence::None);
  const SurfacePtr mostly_zero = make_surface(
      [](auto x, auto y, auto z) {
        using std::max;
        auto r = max(x - 0.75, 0.0 * x);
        return r * r * r * (y * y + z * z - 0.25);
      },
      kCube);
  EXPECT_EQ(zero_function_evidence(*mostly_zero, kCube), ZeroEvidence::None);
  // NaN or infinite samples are not evidence (the meshers report them).
  EXPECT_EQ(evidence("0*sqrt(-1-x^2)"), ZeroEvidence::None);
}

/// Meshes `s` with each method at the default settings and expects NoSurfaceError whose message
/// `check` accepts, well before the time the octree needed to give up before (15 to 145 s): the bound is
/// generous (sanitizer builds, a loaded machine); it catches a return of that subdivision, not speed.
void expect_quick_no_surface(const Surface& s, const std::function<void(const std::string&)>& check) {
  for (Method method : {Method::Projection, Method::MarchingCubes}) {
    SCOPED_TRACE(method_name(method));
    Settings settings;  // defaults: max_depth 8, grid 64
    settings.method = method;
    const auto start = std::chrono::steady_clock::now();
    try {
      mesh_surface(s, settings);
      ADD_FAILURE() << "no error";
    } catch (const NoSurfaceError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("no surface in the box", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos);
      check(message);
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  }
}

TEST(ZeroFunction, MeshSurfaceRejectsItFastForBothMethods) {
  const SurfacePtr callable = make_surface([](auto x, auto, auto) { return x - x; }, kCube);
  const SurfacePtr formula = resolve_surface("0*x", kCube);
  for (const Surface* s : {callable.get(), formula.get()})
    expect_quick_no_surface(*s, [](const std::string& message) {
      EXPECT_EQ(message.rfind("no surface in the box -1,-1,-1,1,1,1: f is identically zero there", 0), 0u)
          << message;
    });
}

TEST(ZeroFunction, ConstantNonzeroIsNoSurfaceAndFast) {
  const SurfacePtr callable = make_surface([](auto x, auto, auto) { return 1.0 + 0.0 * x; }, kCube);
  const SurfacePtr one = resolve_surface("1", kCube);
  const SurfacePtr minus = resolve_surface("-2+0*y", kCube);
  for (const Surface* s : {callable.get(), one.get(), minus.get()})
    expect_quick_no_surface(*s, [](const std::string& message) {
      EXPECT_EQ(message.find("identically zero"), std::string::npos) << message;
    });
}

TEST(ZeroFunction, LegitimateSurfacesStillMesh) {
  // A plane through the samples' symmetry plane and a sphere through dyadic points mesh as before.
  for (const char* formula : {"x", "x^2+y^2+z^2-0.25"})
    for (Method method : {Method::Projection, Method::MarchingCubes}) {
      SCOPED_TRACE(std::string(formula) + " " + method_name(method));
      Settings settings;
      settings.method = method;
      settings.grid = 16;
      settings.edge_length = 0.25;
      EXPECT_GT(mesh_surface(*resolve_surface(formula, kCube), settings).vertex_count(), 0u);
    }
}

}  // namespace
}  // namespace isopatch
