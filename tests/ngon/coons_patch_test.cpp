// The multi-sided C0 Coons patch (Salvi 2020) and its polyline boundary curves: boundary
// interpolation, planarity for planar straight-sided loops, partition of unity of the ribbon weights.
#include "ngon/coons_patch.hpp"

#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "ngon/barycentric.hpp"

namespace isopatch {
namespace {

constexpr CoordinateKind kCoonsKinds[] = {CoordinateKind::Wachspress, CoordinateKind::MeanValue};

Vec3 random_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  return {unit(rng), unit(rng), unit(rng)};
}

/// A cubic Bezier from a to b with random inner control points, sampled at `samples` + 1 parameters.
PolylineCurve random_cubic(const Vec3& a, const Vec3& b, int samples, std::mt19937& rng) {
  const Vec3 c1 = a + 0.5 * random_point(rng), c2 = b + 0.5 * random_point(rng);
  std::vector<Vec3> points;
  for (int j = 0; j <= samples; ++j) {
    const double u = static_cast<double>(j) / samples, v = 1.0 - u;
    points.push_back(v * v * v * a + 3.0 * v * v * u * c1 + 3.0 * v * u * u * c2 + u * u * u * b);
  }
  return PolylineCurve(std::move(points));
}

std::vector<PolylineCurve> random_loop(int n, std::mt19937& rng) {
  std::vector<Vec3> corners;
  for (int k = 0; k < n; ++k) corners.push_back(random_point(rng));
  std::vector<PolylineCurve> curves;
  for (int k = 0; k < n; ++k)
    curves.push_back(random_cubic(corners[static_cast<std::size_t>(k)],
                                  corners[static_cast<std::size_t>((k + 1) % n)], 100, rng));
  return curves;
}

Vec3 evaluate_at(const CoonsPatch& patch, const Domain& domain, const Vec2& x, CoordinateKind kind) {
  std::vector<double> lambda(static_cast<std::size_t>(domain.sides()));
  barycentric_coordinates(domain, x, kind, lambda);
  return patch.evaluate(lambda);
}

TEST(PolylineCurve, ChordLengthParameterAndEndDerivatives) {
  // Segments of lengths 1, 2 and 1: the knots are 0, 1/4, 3/4, 1.
  const PolylineCurve c({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 2, 0), Vec3(1, 2, 1)});
  EXPECT_DOUBLE_EQ(c.length(), 4.0);
  EXPECT_EQ(c.point(0.0), Vec3(0, 0, 0));
  EXPECT_EQ(c.point(1.0), Vec3(1, 2, 1));
  EXPECT_NEAR((c.point(0.5) - Vec3(1, 1, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((c.point(0.125) - Vec3(0.5, 0, 0)).norm(), 0.0, 1e-15);
  // Derivatives with respect to the normalized parameter: the segment divided by its knot span.
  EXPECT_NEAR((c.start_derivative() - Vec3(4, 0, 0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((c.end_derivative() - Vec3(0, 0, 4)).norm(), 0.0, 1e-14);
  // Equal parameter steps are equal arc-length steps.
  for (int i = 0; i < 8; ++i) {
    const double step = (c.point((i + 1) / 8.0) - c.point(i / 8.0)).norm();
    EXPECT_LE(step, 0.5 + 1e-12);
  }
  EXPECT_THROW(PolylineCurve({Vec3::Zero()}), InputError);
  EXPECT_THROW(PolylineCurve({Vec3::Zero(), Vec3::Zero()}), InputError);
}

TEST(CoonsPatch, InterpolatesRandomBoundaryCurves) {
  std::mt19937 rng(20200226);
  for (int n = 3; n <= 8; ++n) {
    const std::vector<PolylineCurve> curves = random_loop(n, rng);
    const CoonsPatch patch(curves);
    const Domain domain(n);
    for (CoordinateKind kind : kCoonsKinds)
      for (int k = 0; k < n; ++k)
        for (int j = 0; j <= 20; ++j) {
          const double t = j / 20.0;
          const Vec3 p = evaluate_at(patch, domain, domain.side_point(k, t), kind);
          EXPECT_LT((p - curves[static_cast<std::size_t>(k)].point(t)).norm(), 1e-9)
              << "n = " << n << ", side " << k << ", t = " << t;
        }
  }
}

TEST(CoonsPatch, PlanarStraightLoopStaysInItsPlane) {
  for (int n = 3; n <= 16; ++n) {
    // A convex planar polygon (an ellipse's inscribed n-gon) in a tilted plane.
    const Vec3 e1 = Vec3(1, 1, 0).normalized(), e2 = Vec3(-1, 1, 2).normalized();
    const Vec3 origin(0.3, -0.2, 0.5), normal = e1.cross(e2);
    std::vector<Vec3> corners;
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * std::acos(-1.0) * k / n + 0.1;
      corners.push_back(origin + 2.0 * std::cos(a) * e1 + std::sin(a) * e2);
    }
    std::vector<PolylineCurve> curves;
    for (int k = 0; k < n; ++k)
      curves.emplace_back(std::vector<Vec3>{corners[static_cast<std::size_t>(k)],
                                            corners[static_cast<std::size_t>((k + 1) % n)]});
    const CoonsPatch patch(curves);
    const Domain domain(n);
    std::mt19937 rng(static_cast<unsigned>(n));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
      const int k = static_cast<int>(rng() % static_cast<unsigned>(n));
      double s = unit(rng), t = unit(rng);
      if (s + t > 1.0) s = 1.0 - s, t = 1.0 - t;
      const Vec2 x = s * domain.vertex(k) + t * domain.vertex(k + 1);
      const Vec3 p = evaluate_at(patch, domain, x, CoordinateKind::Wachspress);
      EXPECT_LT(std::abs((p - origin).dot(normal)), 1e-12) << "n = " << n;
    }
  }
}

TEST(CoonsPatch, RibbonWeightsArePartitionOfUnity) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 3; n <= 16; ++n) {
    const Domain domain(n);
    for (CoordinateKind kind : kCoonsKinds)
      for (int trial = 0; trial < 50; ++trial) {
        const int k = static_cast<int>(rng() % static_cast<unsigned>(n));
        double s = unit(rng), t = unit(rng);
        if (s + t > 1.0) s = 1.0 - s, t = 1.0 - t;
        const Vec2 x = s * domain.vertex(k) + t * domain.vertex(k + 1);
        std::vector<double> lambda(static_cast<std::size_t>(n)), w(static_cast<std::size_t>(n));
        barycentric_coordinates(domain, x, kind, lambda);
        CoonsPatch::ribbon_weights(lambda, w);
        EXPECT_NEAR(std::accumulate(w.begin(), w.end(), 0.0), 1.0, 1e-13);
        for (double wi : w) EXPECT_GE(wi, -1e-15);
      }
  }
}

TEST(CoonsPatch, RejectsOpenLoopsAndBadSizes) {
  std::mt19937 rng(3);
  std::vector<PolylineCurve> curves = random_loop(5, rng);
  curves[2] = PolylineCurve({curves[2].front(), curves[2].back() + Vec3(0.1, 0, 0)});
  EXPECT_THROW(CoonsPatch{curves}, InputError);
  std::vector<PolylineCurve> two = random_loop(2, rng);
  EXPECT_THROW(CoonsPatch{two}, InputError);
}

}  // namespace
}  // namespace isopatch
