// find_singular_points (singular_points.hpp): cusps, nodes, tangent spheres, a self-intersection curve,
// the regular catalogue surfaces, callables, budgets, bad input and thread counts.
#include <isopatch/catalogue.hpp>
#include <isopatch/error.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/singular_points.hpp>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "test_surfaces.hpp"

#include <tbb/task_arena.h>

namespace isopatch {
namespace {

Box cube(double a) {
  return Box{Vec3::Constant(-a), Vec3::Constant(a)};
}

SurfacePtr formula(const std::string& f, const Box& box) {
  return expression_surface(f, box);
}

/// The figure-8 Klein bottle as a polynomial (its self-intersection is a circle of singular points).
const char* const kKlein = "(x^2+y^2+z^2+2*y-1)*((x^2+y^2+z^2-2*y-1)^2-8*z^2)+16*x*z*(x^2+y^2+z^2-2*y-1)";
/// The Barth-type surface of bench/hard_shapes.py ("Barth octic"; of degree 10), with the golden ratio.
const char* const kBarth =
    "p=(1+sqrt(5))/2; (x^2-p^4*y^2)*(y^2-p^4*z^2)*(z^2-p^4*x^2)*(x^4+y^4+z^4-2*x^2*y^2-2*x^2*z^2-2*y^2*z^2)"
    "-(1+2*p)/4*(x^2+y^2+z^2-1)^2";

SingularPoints timed(const Surface& s, const Box& box, const SingularSearchSettings& settings = {}) {
  const auto t0 = std::chrono::steady_clock::now();
  SingularPoints found = find_singular_points(s, box, settings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%-12s %s: %zu points, %zu curves, %zu samples, %zu boxes, %zu starts, %zu converged, %.3f s\n",
              s.name().substr(0, 12).c_str(), status_name(found.status), found.isolated_points(),
              found.curves(), found.points.size(), found.boxes, found.starts, found.converged, seconds);
  return found;
}

/// The samples of component k of `found`.
std::vector<Vec3> samples_of(const SingularPoints& found, std::size_t k) {
  std::size_t first = 0;
  for (std::size_t i = 0; i < k; ++i) first += found.components[i].samples;
  return {found.points.begin() + first, found.points.begin() + first + found.components[k].samples};
}

TEST(SingularPoints, HeartHasItsTwoCuspsAndADegenerateEquator) {
  const SurfacePtr heart = catalogue_surface("heart");
  const SingularPoints found = timed(*heart, heart->box());
  EXPECT_EQ(found.status, SingularSearchStatus::Complete);
  EXPECT_TRUE(found.reason.empty());
  EXPECT_EQ(found.isolated_points(), 2u);
  EXPECT_EQ(found.curves(), 0u);
  ASSERT_GE(found.components.size(), 2u);
  // Singular components first, sorted by position: (0, 0, -1), then (0, 0, 1).
  EXPECT_LT((found.components[0].position - Vec3(0, 0, -1)).norm(), 1e-6) << found.components[0].position;
  EXPECT_LT((found.components[1].position - Vec3(0, 0, 1)).norm(), 1e-6) << found.components[1].position;
  EXPECT_EQ(describe_singular_points(found, heart->box()),
            "2 singular points of f = 0 (grad f = 0) in the box: (0, 0, -1), (0, 0, 1)");
  // f = (u - c^(1/3) z)(u^2 + u c^(1/3) z + c^(2/3) z^2), u = x^2 + 9/4 y^2 + z^2 - 1, c = x^2 + 9/80 y^2:
  // grad f = 0 also on the ellipse u = z = 0, where f = 0 is smooth. One curve, marked as such.
  ASSERT_EQ(found.components.size(), 3u);
  EXPECT_EQ(found.degenerate(), 1u);
  const SingularComponent& equator = found.components[2];
  EXPECT_TRUE(equator.smooth_sheet);
  EXPECT_TRUE(equator.curve);
  EXPECT_NEAR(equator.extent.lo.x(), -1.0, 0.02);
  EXPECT_NEAR(equator.extent.hi.x(), 1.0, 0.02);
  EXPECT_NEAR(equator.extent.lo.y(), -2.0 / 3.0, 0.02);
  EXPECT_NEAR(equator.extent.hi.y(), 2.0 / 3.0, 0.02);
  // The ellipse is about 5.3 long: at least one sample per 3 spacings along it.
  EXPECT_GT(static_cast<double>(equator.samples), 5.3 / (3.0 * found.spacing));
  for (const Vec3& p : samples_of(found, 2)) {
    EXPECT_NEAR(p.z(), 0.0, 1e-6);
    EXPECT_NEAR(p.x() * p.x() + 2.25 * p.y() * p.y(), 1.0, 1e-6);
  }
  EXPECT_NE(describe_degenerate_points(found, heart->box()).find("a curve of"), std::string::npos);
}

TEST(SingularPoints, ConeApexAnywhereInTheBox) {
  // The apex off the centre and off every split plane of the box.
  const Box box{Vec3(-0.71, -0.93, -1.13), Vec3(1.29, 0.83, 0.61)};
  const Vec3 apex(0.123, -0.0456, 0.0789);
  const SurfacePtr cone = formula("(x-0.123)^2 + (y+0.0456)^2 - (z-0.0789)^2", box);
  const SingularPoints found = timed(*cone, box);
  EXPECT_EQ(found.status, SingularSearchStatus::Complete);
  ASSERT_EQ(found.components.size(), 1u);
  EXPECT_FALSE(found.components[0].curve);
  EXPECT_FALSE(found.components[0].smooth_sheet);
  EXPECT_LT((found.components[0].position - apex).norm(), 1e-9);
}

TEST(SingularPoints, TwoSpheresTouchingAtOnePoint) {
  const Box box{Vec3(-2.3, -1.2, -1.1), Vec3(2.2, 1.3, 1.2)};
  const SurfacePtr spheres = formula("((x-1)^2 + y^2 + z^2 - 1)*((x+1)^2 + y^2 + z^2 - 1)", box);
  const SingularPoints found = timed(*spheres, box);
  EXPECT_EQ(found.status, SingularSearchStatus::Complete);
  ASSERT_EQ(found.components.size(), 1u);
  EXPECT_FALSE(found.components[0].curve);
  EXPECT_FALSE(found.components[0].smooth_sheet);  // two sheets touch: the surface is singular
  // f = |p|^4 - 4 x^2 near 0: Gauss-Newton converges only linearly along the tangent plane.
  EXPECT_LT((found.components[0].position - Vec3::Zero()).norm(), 1e-4);
}

TEST(SingularPoints, KleinBottleSelfIntersectionIsOneCurve) {
  const SurfacePtr klein = formula(kKlein, cube(3.2));
  const SingularPoints found = timed(*klein, cube(3.2));
  EXPECT_EQ(found.status, SingularSearchStatus::Complete);
  EXPECT_EQ(found.isolated_points(), 0u);
  EXPECT_EQ(found.degenerate(), 0u);
  ASSERT_EQ(found.curves(), 1u);
  // In z = 0, f = (r^2 + 2y - 1)(r^2 - 2y - 1)^2: the sheets cross on the circle x^2 + (y - 1)^2 = 2.
  const SingularComponent& c = found.components[0];
  EXPECT_NEAR(c.extent.lo.x(), -std::sqrt(2.0), 0.02);
  EXPECT_NEAR(c.extent.hi.x(), std::sqrt(2.0), 0.02);
  EXPECT_NEAR(c.extent.lo.y(), 1.0 - std::sqrt(2.0), 0.02);
  EXPECT_NEAR(c.extent.hi.y(), 1.0 + std::sqrt(2.0), 0.02);
  // Its length 2 pi sqrt 2 = 8.9, sampled at least every 3 spacings and at most every spacing.
  const double length = 2.0 * std::numbers::pi * std::sqrt(2.0);
  EXPECT_GT(static_cast<double>(c.samples), length / (3.0 * found.spacing));
  EXPECT_LE(static_cast<double>(c.samples), length / found.spacing + 1.0);
  for (const Vec3& p : samples_of(found, 0)) {
    EXPECT_NEAR(p.z(), 0.0, 1e-9);
    EXPECT_NEAR(std::hypot(p.x(), p.y() - 1.0), std::sqrt(2.0), 1e-9);
  }
  const std::string text = describe_singular_points(found, cube(3.2));
  EXPECT_EQ(text.rfind("1 curve of singular points of f = 0 (grad f = 0) in the box: a curve of ", 0), 0u)
      << text;
}

TEST(SingularPoints, BarthNodesAreEveryNodeInTheBox) {
  const SurfacePtr barth = formula(kBarth, cube(1.9));
  const SingularPoints found = timed(*barth, cube(1.9));
  EXPECT_EQ(found.status, SingularSearchStatus::Complete) << found.reason;
  EXPECT_EQ(found.curves(), 0u);
  EXPECT_EQ(found.degenerate(), 0u);
  // An independent search (multistart Newton on grad f = 0 from a 24^3 grid, in Python with sympy) found 90
  // nodes in the box, all on the unit sphere: where two of the ten planes of the product meet it.
  ASSERT_EQ(found.isolated_points(), 90u);
  std::vector<Vec3> nodes;
  for (const SingularComponent& c : found.components) {
    nodes.push_back(c.position);
    // A node by its own residual: f and grad f vanish, the Hessian is nondegenerate and indefinite.
    const SecondOrder s = barth->second_order(c.position);
    EXPECT_LT(std::abs(s.value), 1e-12);
    EXPECT_LT(s.gradient.norm(), 1e-12);
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(s.hessian);
    EXPECT_LT(eigen.eigenvalues()[0], -1.0);
    EXPECT_GT(eigen.eigenvalues()[2], 1.0);
    EXPECT_GT(eigen.eigenvalues().cwiseAbs().minCoeff(), 1.0);
    EXPECT_NEAR(c.position.norm(), 1.0, 1e-9);
  }
  // The set has the surface's symmetries: sign changes and the cyclic permutation of the axes.
  const auto has = [&](const Vec3& q) {
    return std::any_of(nodes.begin(), nodes.end(), [&](const Vec3& n) { return (n - q).norm() < 1e-9; });
  };
  for (const Vec3& n : nodes) {
    EXPECT_TRUE(has(Vec3(-n.x(), n.y(), n.z()))) << n.transpose();
    EXPECT_TRUE(has(Vec3(n.x(), -n.y(), n.z()))) << n.transpose();
    EXPECT_TRUE(has(Vec3(n.y(), n.z(), n.x()))) << n.transpose();
  }
  EXPECT_TRUE(has(Vec3(1, 0, 0)));
  EXPECT_TRUE(has(Vec3(0.5, (1.0 + std::sqrt(5.0)) / 4.0, (std::sqrt(5.0) - 1.0) / 4.0)));
  // 8 listed, then the rest counted.
  const std::string text = describe_singular_points(found, cube(1.9));
  EXPECT_EQ(text.rfind("90 singular points of f = 0 (grad f = 0) in the box: (-1, 0, 0), ", 0), 0u) << text;
  EXPECT_NE(text.find(" and 82 more"), std::string::npos) << text;
}

TEST(SingularPoints, RegularCatalogueSurfacesHaveNone) {
  for (const CatalogueEntry& e : catalogue()) {
    const SurfacePtr s = catalogue_surface(e.name);
    const SingularPoints found = timed(*s, s->box());
    EXPECT_EQ(found.status, SingularSearchStatus::Complete) << e.name;
    if (e.smooth)
      EXPECT_TRUE(found.components.empty()) << e.name << ": " << describe_singular_points(found, s->box());
    else
      EXPECT_GT(found.isolated_points() + found.curves(), 0u) << e.name;
  }
  // Clipped by a box through the surface's saddle-rich middle, the gyroid still has none.
  const SurfacePtr gyroid = formula("sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)", cube(3.1));
  EXPECT_TRUE(find_singular_points(*gyroid, cube(3.1)).components.empty());
}

TEST(SingularPoints, CallableSurfaceIsNotSearched) {
  const SurfacePtr s = test::sphere();
  const SingularPoints found = find_singular_points(*s, s->box());
  EXPECT_EQ(found.status, SingularSearchStatus::NotSearched);
  EXPECT_FALSE(found.searched());
  EXPECT_FALSE(found.reason.empty());
  EXPECT_TRUE(found.components.empty());
  EXPECT_EQ(found.boxes, 0u);
}

TEST(SingularPoints, BudgetsStopTheSearchAndSaySo) {
  const SurfacePtr heart = catalogue_surface("heart");
  SingularSearchSettings few;
  few.max_boxes = 200;
  const SingularPoints boxes = find_singular_points(*heart, heart->box(), few);
  EXPECT_EQ(boxes.status, SingularSearchStatus::BudgetExhausted);
  EXPECT_LE(boxes.boxes, 200u);
  EXPECT_NE(boxes.reason.find("200 boxes"), std::string::npos) << boxes.reason;
  SingularSearchSettings starts;
  starts.max_starts = 10;
  const SingularPoints thinned = find_singular_points(*heart, heart->box(), starts);
  EXPECT_EQ(thinned.status, SingularSearchStatus::BudgetExhausted);
  EXPECT_EQ(thinned.starts, 10u);
  EXPECT_NE(thinned.reason.find("Newton starts"), std::string::npos) << thinned.reason;
  // What a stopped search found is listed with the budget said in the same line (ten starts on the
  // heart find nothing, so the complete search's cusps stand for a stopped one's).
  SingularPoints stopped = find_singular_points(*heart, heart->box());
  ASSERT_GT(stopped.isolated_points(), 0u);
  EXPECT_EQ(describe_singular_points(stopped, heart->box()).find("stopped at its budget"), std::string::npos);
  stopped.status = SingularSearchStatus::BudgetExhausted;
  EXPECT_NE(describe_singular_points(stopped, heart->box()).find("stopped at its budget"), std::string::npos);
}

TEST(SingularPoints, ARegionKeepsOnlyThePointsInside) {
  const SurfacePtr heart = catalogue_surface("heart");
  SingularSearchSettings upper;
  upper.inside = [](const Vec3& p) { return p.z() > 0.5; };
  const SingularPoints found = find_singular_points(*heart, heart->box(), upper);
  ASSERT_EQ(found.components.size(), 1u);
  EXPECT_LT((found.components[0].position - Vec3(0, 0, 1)).norm(), 1e-6);
}

TEST(SingularPoints, BadInputIsATypedError) {
  const SurfacePtr heart = catalogue_surface("heart");
  EXPECT_THROW(find_singular_points(*heart, Box{Vec3::Zero(), Vec3::Zero()}), InputError);
  const auto setting_of = [&](SingularSearchSettings s) {
    try {
      find_singular_points(*heart, heart->box(), s);
    } catch (const SettingError& e) {
      return e.setting();
    }
    return std::string("none");
  };
  SingularSearchSettings s;
  s.max_boxes = 0;
  EXPECT_EQ(setting_of(s), "max_boxes");
  s = {};
  s.max_starts = 0;
  EXPECT_EQ(setting_of(s), "max_starts");
  s = {};
  s.min_box_size = -1.0;
  EXPECT_EQ(setting_of(s), "min_box_size");
  s = {};
  s.spacing = std::nan("");
  EXPECT_EQ(setting_of(s), "spacing");
  s = {};
  s.tolerance = 1.0;
  EXPECT_EQ(setting_of(s), "tolerance");
}

TEST(SingularPoints, SameResultForAnyThreadCount) {
  const SurfacePtr klein = formula(kKlein, cube(3.2));
  const auto run = [&](int threads) {
    tbb::task_arena arena(threads);
    return arena.execute([&] { return find_singular_points(*klein, cube(3.2)); });
  };
  const SingularPoints one = run(1), three = run(3);
  EXPECT_EQ(one.boxes, three.boxes);
  EXPECT_EQ(one.starts, three.starts);
  ASSERT_EQ(one.points.size(), three.points.size());
  for (std::size_t i = 0; i < one.points.size(); ++i) EXPECT_EQ(one.points[i], three.points[i]) << i;
  ASSERT_EQ(one.components.size(), three.components.size());
  for (std::size_t i = 0; i < one.components.size(); ++i)
    EXPECT_EQ(one.components[i].position, three.components[i].position);
}

}  // namespace
}  // namespace isopatch
