// Predictor-corrector tracing of a = b = 0 (csg/curve_tracer.hpp) and the Newton iterations it uses
// (surface/curve_point.hpp).
#include <gtest/gtest.h>

#include <isopatch/resolve_surface.hpp>

#include <cmath>

#include "csg/curve_tracer.hpp"
#include "surface/curve_point.hpp"

namespace isopatch {
namespace {

const Box kTraceBox{Vec3::Constant(-2.0), Vec3::Constant(2.0)};

double on(const Surface& f, const Vec3& p) {
  const ValueGradient g = f.value_gradient(p);
  return std::abs(g.value) / g.gradient.norm();
}

TEST(CurvePoint, NewtonSettlesOnTwoAndThreeFunctions) {
  const SurfacePtr sphere = expression_surface("x^2+y^2+z^2-1", kTraceBox);
  const SurfacePtr plane = expression_surface("z-0.3", kTraceBox);
  const SurfacePtr other = expression_surface("x-0.2", kTraceBox);
  CurvePointParams p{1e-14, 0.5, 1.0};
  const auto q = settle_on_curve(*sphere, *plane, {0.9, 0.1, 0.2}, p);
  ASSERT_TRUE(q);
  EXPECT_LT(on(*sphere, *q), 1e-13);
  EXPECT_LT(on(*plane, *q), 1e-13);
  const auto c = settle_on_corner(*sphere, *plane, *other, {0.2, 0.9, 0.3}, p);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->y(), std::sqrt(1.0 - 0.09 - 0.04), 1e-12);
  // Tangent functions (a sphere on the plane z = 1) have no curve: from beside the contact Newton
  // either gives up (parallel gradients) or ends at the contact point itself.
  const SurfacePtr tangent = expression_surface("z-1", kTraceBox);
  const auto touch = settle_on_curve(*sphere, *tangent, {0.05, 0.0, 1.02}, p);
  if (touch) {
    EXPECT_LT((*touch - Vec3(0.0, 0.0, 1.0)).norm(), 1e-4);
  }
  EXPECT_NEAR(gradient_sine(*sphere, *tangent, {0.0, 0.0, 1.0}), 0.0, 1e-15);
}

TEST(CurveTracer, ACircleClosesOnItsStart) {
  const SurfacePtr sphere = expression_surface("x^2+y^2+z^2-1", kTraceBox);
  const SurfacePtr plane = expression_surface("z-0.6", kTraceBox);
  TraceParams t;
  t.step = 0.05;
  t.tolerance = 1e-14;
  t.box = kTraceBox;
  t.owner = [](const Vec3&) { return -1; };
  const TracedPath path = trace_curve(*sphere, *plane, {0.8, 0.0, 0.6}, 1.0, t);
  ASSERT_EQ(path.end, TraceEnd::Closed);
  EXPECT_EQ(path.points.back(), path.points.front());
  double length = 0.0;
  for (std::size_t k = 0; k < path.points.size(); ++k) {
    EXPECT_LT(on(*sphere, path.points[k]), 1e-12);
    EXPECT_LT(on(*plane, path.points[k]), 1e-12);
    if (k > 0) length += (path.points[k] - path.points[k - 1]).norm();
  }
  EXPECT_NEAR(length, 2.0 * std::numbers::pi * 0.8, 1e-3);
}

TEST(CurveTracer, AnEdgeEndsAtTheCornerWhereAThirdFaceTakesOver) {
  const SurfacePtr x = expression_surface("x-1", kTraceBox), y = expression_surface("y-1", kTraceBox),
                   z = expression_surface("z-1", kTraceBox);
  TraceParams t;
  t.step = 0.07;
  t.tolerance = 1e-14;
  t.box = kTraceBox;
  t.owner = [](const Vec3& p) { return p.z() > 1.0 ? 7 : -1; };
  t.third_function = [&](int) -> const Surface& { return *z; };
  // grad x cross grad y = +z: upwards to the corner (1, 1, 1).
  const TracedPath path = trace_curve(*x, *y, {1.0, 1.0, 0.0}, 1.0, t);
  ASSERT_EQ(path.end, TraceEnd::Corner);
  EXPECT_EQ(path.third, 7);
  EXPECT_LT((path.points.back() - Vec3(1.0, 1.0, 1.0)).norm(), 1e-13);
  for (std::size_t k = 1; k < path.points.size(); ++k) EXPECT_GT(path.points[k].z(), path.points[k - 1].z());
  // A target on the way ends it there.
  t.targets = {Vec3(1.0, 1.0, 0.5)};
  EXPECT_EQ(trace_curve(*x, *y, {1.0, 1.0, 0.0}, 1.0, t).points.back(), Vec3(1.0, 1.0, 0.5));
}

}  // namespace
}  // namespace isopatch
