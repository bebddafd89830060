// grad f vanishing on f = 0 (a repeated factor): rejected up front with a one-line SingularSurfaceError
// by the projection mesher and every clean-up, from the slope of f across sampled crossings; never for
// a regular surface, nor for surfaces with isolated singular points or curves (cones, crossing sheets).
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "surface/singular_level_set.hpp"

namespace isopatch {
namespace {

const Box kWideCube{Vec3::Constant(-1.5), Vec3::Constant(1.5)};

SingularEvidence singular_evidence(const std::string& formula) {
  return singular_level_set_evidence(*resolve_surface(formula, kWideCube), kWideCube);
}

TEST(SingularLevelSet, RepeatedFactorsAreSingularEverywhere) {
  for (const char* formula : {"x^3", "(x^2+y^2+z^2-1)^3", "(x^2+y^2+z^2-1)^5", "(x+y-0.3*z)^3*exp(x)"}) {
    SCOPED_TRACE(formula);
    const SingularEvidence e = singular_evidence(formula);
    EXPECT_GE(e.roots, 8u);
    EXPECT_EQ(e.singular, e.roots);
  }
  // Half the sampled surface is the repeated plane, half the simple sphere.
  const SingularEvidence mixed = singular_evidence("(x-y)^3*(x^2+y^2+z^2-1)");
  EXPECT_GT(mixed.singular, mixed.roots / 5);
  EXPECT_LT(mixed.singular, mixed.roots);
}

TEST(SingularLevelSet, RegularSurfacesAndIsolatedSingularitiesAreNot) {
  // A cone (singular apex), three crossing planes, a cusp-like cubic with a linear term, a shell of
  // thickness 0.01 (grad f small but regular), a steep exponential, and catalogue surfaces.
  for (const char* formula : {"x^2+y^2-z^2", "x*y*z", "x^3+0.001*y", "(x^2+y^2+z^2-1)^2-0.0001",
                              "exp(8*x)-exp(4*y)", "1e-9*(x^2+y^2+z^2-1)"}) {
    SCOPED_TRACE(formula);
    const SingularEvidence e = singular_evidence(formula);
    EXPECT_GE(e.roots, 8u);
    EXPECT_EQ(e.singular, 0u);
  }
  for (const char* name : {"torus", "tanglecube", "chmutov6"}) {  // in their catalogue boxes
    SCOPED_TRACE(name);
    const SurfacePtr s = resolve_surface(name, std::nullopt);
    const SingularEvidence e = singular_level_set_evidence(*s, s->box());
    EXPECT_GE(e.roots, 8u);
    EXPECT_EQ(e.singular, 0u);
  }
  // No crossing at all: no evidence either way (the meshers report the missing surface).
  EXPECT_EQ(singular_evidence("x^2+y^2+z^2+1").roots, 0u);
}

TEST(SingularLevelSet, ProjectionAndCleanUpRejectItMarchingCubesAloneMeshes) {
  const SurfacePtr cubed = resolve_surface("(x^2+y^2+z^2-1)^3", kWideCube);
  Settings settings;
  settings.box = kWideCube;
  settings.edge_length = 0.3;
  try {
    mesh_surface(*cubed, settings);
    ADD_FAILURE() << "no error";
  } catch (const SingularSurfaceError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("grad f vanishes on f = 0 at 100% of ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  settings.method = Method::MarchingCubes;
  settings.grid = 16;
  settings.fair_iterations = 2;
  EXPECT_THROW(mesh_surface(*cubed, settings), SingularSurfaceError);
  settings.fair_iterations = 0;
  settings.remesh_iterations = 1;
  EXPECT_THROW(mesh_surface(*cubed, settings), SingularSurfaceError);
  settings.remesh_iterations = 0;
  EXPECT_GT(mesh_surface(*cubed, settings).vertex_count(), 0u);  // signs are all marching cubes needs
}

}  // namespace
}  // namespace isopatch
