// From the command line's surface argument to a Surface: names, formulas, files, params and errors.
#include "test_surfaces.hpp"

#include <isopatch/catalogue.hpp>
#include <isopatch/error.hpp>
#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace isopatch {
namespace {

const Box kUnitBox{Vec3::Constant(-1.5), Vec3::Constant(1.5)};

template <class E, class F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected exception not thrown";
  return {};
}

TEST(ResolveSurface, CatalogueNamesUseTheirBoxUnlessOneIsGiven) {
  const SurfacePtr torus = resolve_surface("torus", std::nullopt);
  EXPECT_EQ(torus->name(), "torus");
  EXPECT_EQ(torus->box().lo, find_in_catalogue("torus")->box.lo);
  EXPECT_EQ(torus->box().hi, find_in_catalogue("torus")->box.hi);
  const SurfacePtr boxed = resolve_surface("  torus ", kUnitBox);
  EXPECT_EQ(boxed->box().lo, kUnitBox.lo);
  EXPECT_NEAR(boxed->value(Vec3(1.4, 0, 0)), 0.0, 1e-12);
}

TEST(ResolveSurface, EveryCatalogueEntryCompiles) {
  for (const CatalogueEntry& e : catalogue()) {
    const SurfacePtr s = catalogue_surface(e.name);
    EXPECT_EQ(s->name(), e.name);
    const double v = s->value(e.box.centre());
    EXPECT_TRUE(std::isfinite(v)) << e.name;
    const auto bound = s->bound(e.box);
    ASSERT_TRUE(bound.has_value());
    EXPECT_TRUE(bound->contains(v)) << e.name;
    EXPECT_TRUE(bound->contains_zero()) << e.name << ": the surface crosses its box";
    ASSERT_TRUE(s->gradient_bound(e.box).has_value());
  }
}

TEST(ResolveSurface, UnknownNamesSuggestTheClosest) {
  EXPECT_EQ(message_of<UnknownSurfaceError>([] { resolve_surface("tours", std::nullopt); }),
            "unknown surface 'tours' (did you mean 'torus'?)");
  EXPECT_EQ(message_of<UnknownSurfaceError>([] { catalogue_surface("sphear"); }),
            "unknown surface 'sphear' (did you mean 'sphere'?)");
  // A bare identifier is a name even with a box; far from every entry, the message lists them.
  const std::string far = message_of<UnknownSurfaceError>([] { resolve_surface("qqqqqqqqqq", kUnitBox); });
  EXPECT_NE(far.find("sphere"), std::string::npos) << far;
  EXPECT_NE(far.find("heart"), std::string::npos) << far;
}

TEST(ResolveSurface, FormulasNeedABox) {
  EXPECT_EQ(message_of<InputError>([] { resolve_surface("x^2 + y^2 + z^2 - 1", std::nullopt); }),
            "a formula needs a box");
  try {
    resolve_surface("x^2 + y^2 + z^2 - 1", std::nullopt);
  } catch (const InputError& e) {
    EXPECT_EQ(e.setting(), "box");
  }
  const SurfacePtr s = resolve_surface("x^2 + y^2 + z^2 - 1", kUnitBox);
  EXPECT_DOUBLE_EQ(s->value(Vec3(1, 0, 0)), 0.0);
  EXPECT_EQ(s->box().hi, kUnitBox.hi);
  // A lone variable is a formula (the plane x = 0), not a misspelt name.
  EXPECT_DOUBLE_EQ(resolve_surface("x", kUnitBox)->value(Vec3(0.5, 0, 0)), 0.5);
  EXPECT_THROW(resolve_surface("x", std::nullopt), InputError);
  EXPECT_THROW(resolve_surface("sin(x", kUnitBox), ParseError);
  EXPECT_THROW(expression_surface("x", Box{Vec3::Zero(), Vec3::Zero()}), InputError);
}

TEST(ResolveSurface, ReadsFormulaFiles) {
  const auto path = std::filesystem::temp_directory_path() / "isopatch_expr_resolve_test.txt";
  {
    std::ofstream out(path);
    out << "# a torus, one definition per line\nR = 1\nr = 0.4\n"
           "(x^2 + y^2 + z^2 + R^2 - r^2)^2\n  - 4*R^2*(x^2 + y^2)\n";
  }
  const SurfacePtr s =
      resolve_surface("@" + path.string(), Box{Vec3(-2, -2, -1), Vec3(2, 2, 1)}, {{"r", 0.3}});
  const SurfacePtr reference = test::torus(1.0, 0.3);
  for (const Vec3& p : {Vec3(1.3, 0, 0), Vec3(0.2, -0.9, 0.3), Vec3(1, 1, 0.1)})
    EXPECT_NEAR(s->value(p), reference->value(p), 1e-12);
  EXPECT_THROW(resolve_surface("@" + path.string(), std::nullopt), InputError);
  std::filesystem::remove(path);
  const std::string missing = message_of<IoError>([&] { resolve_surface("@" + path.string(), kUnitBox); });
  EXPECT_NE(missing.find(path.string()), std::string::npos) << missing;
}

TEST(ResolveSurface, ParamsOverrideCatalogueDefinitions) {
  const SurfacePtr thin = catalogue_surface("torus", {{"r", 0.3}});
  const SurfacePtr reference = test::torus(1.0, 0.3);
  for (const Vec3& p : {Vec3(1.3, 0, 0), Vec3(0.2, -0.9, 0.3)}) {
    EXPECT_NEAR(thin->value(p), reference->value(p), 1e-12);
    EXPECT_LT((thin->value_gradient(p).gradient - reference->value_gradient(p).gradient).norm(), 1e-12);
  }
  const std::string m = message_of<InputError>([] { catalogue_surface("sphere", {{"r", 1.0}}); });
  EXPECT_NE(m.find("r"), std::string::npos) << m;
  EXPECT_NE(m.find("defines nothing"), std::string::npos) << m;
}

TEST(ResolveSurface, ExpressionSurfaceImplementsEveryService) {
  const SurfacePtr s = expression_surface("sin(x) + y*z", kUnitBox, "demo");
  EXPECT_EQ(s->name(), "demo");
  const std::vector<Vec3> points = {Vec3(0.1, 0.2, 0.3), Vec3(-1, 0.5, 1), Vec3(1.2, -0.3, 0.7)};
  std::vector<double> out(points.size());
  s->values(points, out);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(out[i], s->value(points[i]));
    EXPECT_EQ(s->value_gradient(points[i]).value, out[i]);
    EXPECT_EQ(s->second_order(points[i]).value, out[i]);
  }
  const auto bound = s->bound(kUnitBox);
  ASSERT_TRUE(bound.has_value());
  EXPECT_GE(bound->hi, 1.0);
  EXPECT_LE(bound->lo, -1.0);
  EXPECT_EQ(expression_surface("x", kUnitBox)->name(), "x");
}

}  // namespace
}  // namespace isopatch
