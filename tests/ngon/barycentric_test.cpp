#include "ngon/barycentric.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace isopatch {
namespace {

constexpr CoordinateKind kKinds[] = {CoordinateKind::Wachspress, CoordinateKind::MeanValue};

std::vector<double> coordinates(const Domain& domain, const Vec2& x, CoordinateKind kind) {
  std::vector<double> lambda(static_cast<std::size_t>(domain.sides()), -99.0);
  barycentric_coordinates(domain, x, kind, lambda);
  return lambda;
}

double at(const std::vector<double>& lambda, const Domain& domain, int k) {
  return lambda[static_cast<std::size_t>(domain.wrap(k))];
}

/// Uniformly random points strictly inside the domain (a random fan triangle, then a random point of it).
std::vector<Vec2> random_interior_points(const Domain& domain, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, domain.sides() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec2> points;
  while (static_cast<int>(points.size()) < count) {
    const int k = pick(rng);
    double s = unit(rng), t = unit(rng);
    if (s + t >= 1.0) s = 1.0 - s, t = 1.0 - t;
    if (s + t >= 1.0 - 1e-9 || s + t <= 0.0) continue;
    points.push_back(s * domain.vertex(k) + t * domain.vertex(k + 1));
  }
  return points;
}

/// Points at distance `delta` inside from side k at parameter t.
Vec2 near_side(const Domain& domain, int k, double t, double delta) {
  const Vec2 e = (domain.vertex(k + 1) - domain.vertex(k)).normalized();
  return domain.side_point(k, t) + delta * Vec2(-e.y(), e.x());
}

void expect_barycentric(const Domain& domain, const Vec2& x, const std::vector<double>& lambda, double tol) {
  double sum = 0.0;
  Vec2 centroid = Vec2::Zero();
  for (int k = 0; k < domain.sides(); ++k) {
    sum += at(lambda, domain, k);
    centroid += at(lambda, domain, k) * domain.vertex(k);
    EXPECT_GE(at(lambda, domain, k), -1e-15)
        << "n=" << domain.sides() << " k=" << k << " x=" << x.transpose();
    EXPECT_TRUE(std::isfinite(at(lambda, domain, k)));
  }
  EXPECT_NEAR(sum, 1.0, 1e-14) << "x=" << x.transpose();
  EXPECT_LT((centroid - x).norm(), tol) << "n=" << domain.sides() << " x=" << x.transpose();
}

/// The textbook quotient forms, valid away from the boundary: Wachspress w_k = C_k / (A_{k-1} A_k),
/// mean value w_k = (tan(a_{k-1}/2) + tan(a_k/2)) / r_k.
std::vector<double> reference(const Domain& domain, const Vec2& x, CoordinateKind kind) {
  const int n = domain.sides();
  std::vector<double> w(static_cast<std::size_t>(n));
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const Vec2 prev = domain.vertex(k - 1) - x, here = domain.vertex(k) - x, next = domain.vertex(k + 1) - x;
    double wk = 0.0;
    if (kind == CoordinateKind::Wachspress) {
      const double c =
          cross(domain.vertex(k) - domain.vertex(k - 1), domain.vertex(k + 1) - domain.vertex(k - 1));
      wk = c / (cross(prev, here) * cross(here, next));
    } else {
      const double a_prev = std::atan2(cross(prev, here), prev.dot(here));
      const double a_here = std::atan2(cross(here, next), here.dot(next));
      wk = (std::tan(a_prev / 2) + std::tan(a_here / 2)) / here.norm();
    }
    w[static_cast<std::size_t>(k)] = wk;
    sum += wk;
  }
  for (double& v : w) v /= sum;
  return w;
}

TEST(Barycentric, InteriorPointsArePositivePartitionOfUnityWithLinearPrecision) {
  for (int n = 3; n <= 16; ++n) {
    const Domain domain(n);
    for (CoordinateKind kind : kKinds) {
      for (const Vec2& x : random_interior_points(domain, 400, 17u + static_cast<unsigned>(n))) {
        const auto lambda = coordinates(domain, x, kind);
        expect_barycentric(domain, x, lambda, 1e-14);
        for (double l : lambda) EXPECT_GT(l, 0.0);
      }
    }
  }
}

TEST(Barycentric, MatchesTheTextbookQuotientFormsInside) {
  for (int n = 3; n <= 16; ++n) {
    const Domain domain(n);
    for (CoordinateKind kind : kKinds) {
      for (const Vec2& x : random_interior_points(domain, 200, 5u + static_cast<unsigned>(n))) {
        const auto lambda = coordinates(domain, x, kind);
        const auto expected = reference(domain, x, kind);
        for (std::size_t k = 0; k < lambda.size(); ++k) {
          EXPECT_NEAR(lambda[k], expected[k], 1e-10) << "n=" << n << " x=" << x.transpose();
        }
      }
    }
  }
}

TEST(Barycentric, AreLinearOnEachSideWithOnlyTheTwoSideCoordinatesNonZero) {
  for (int n = 3; n <= 16; ++n) {
    const Domain domain(n);
    for (CoordinateKind kind : kKinds) {
      for (int k = 0; k < n; ++k) {
        for (double t : {1e-9, 0.01, 0.1, 0.25, 1.0 / 3.0, 0.5, 0.77, 0.99, 1.0 - 1e-9}) {
          const Vec2 x = domain.side_point(k, t);
          const auto lambda = coordinates(domain, x, kind);
          expect_barycentric(domain, x, lambda, 1e-14);
          EXPECT_NEAR(at(lambda, domain, k), 1.0 - t, 1e-14) << "n=" << n << " k=" << k << " t=" << t;
          EXPECT_NEAR(at(lambda, domain, k + 1), t, 1e-14) << "n=" << n << " k=" << k << " t=" << t;
          for (int j = 2; j < n; ++j) EXPECT_NEAR(at(lambda, domain, k + j), 0.0, 1e-14);
        }
      }
    }
  }
}

TEST(Barycentric, StayAccurateAndContinuousNextToTheBoundary) {
  for (int n = 3; n <= 16; ++n) {
    const Domain domain(n);
    for (CoordinateKind kind : kKinds) {
      for (int k = 0; k < n; ++k) {
        for (double t : {1e-6, 0.3, 0.5, 0.9}) {
          for (double delta : {1e-3, 1e-7, 1e-11, 1e-15}) {
            if (delta > 0.1 * std::min(t, 1.0 - t)) continue;  // would leave the domain past a corner
            const Vec2 x = near_side(domain, k, t, delta);
            const auto lambda = coordinates(domain, x, kind);
            expect_barycentric(domain, x, lambda, 1e-14);
            // The coordinates are Lipschitz: within a modest multiple of delta of the side values.
            const double tol = 1e-13 + 100.0 * delta;
            EXPECT_NEAR(at(lambda, domain, k), 1.0 - t, tol) << n << " " << k << " " << t << " " << delta;
            EXPECT_NEAR(at(lambda, domain, k + 1), t, tol);
          }
        }
      }
    }
  }
}

TEST(Barycentric, InterpolateAtAndNearVertices) {
  for (int n = 3; n <= 16; ++n) {
    const Domain domain(n);
    for (CoordinateKind kind : kKinds) {
      for (int k = 0; k < n; ++k) {
        const auto lambda = coordinates(domain, domain.vertex(k), kind);
        for (int j = 0; j < n; ++j) EXPECT_EQ(at(lambda, domain, j), j == k ? 1.0 : 0.0);
        // Approaching along the inward bisector and along both sides.
        const Vec2 inward = -domain.vertex(k).normalized();
        for (double delta : {1e-4, 1e-9, 1e-13, 1e-15}) {
          for (const Vec2& x : {Vec2(domain.vertex(k) + delta * inward), domain.side_point(k, delta),
                                domain.side_point(k - 1, 1.0 - delta)}) {
            const auto near = coordinates(domain, x, kind);
            expect_barycentric(domain, x, near, 1e-14);
            // The slope of lambda_k near its vertex grows with n (just above 10 for n = 14..16).
            EXPECT_NEAR(at(near, domain, k), 1.0, 1e-13 + std::max(10.0, static_cast<double>(n)) * delta)
                << n << " " << k << " " << delta;
          }
        }
      }
    }
  }
}

TEST(Barycentric, WachspressIsBilinearOnTheSquare) {
  const Domain square(4);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::vector<Vec2> points;
  for (int i = 0; i < 500; ++i) points.emplace_back(coord(rng), coord(rng));
  for (double s : {-1.0, -0.5, 0.0, 0.3, 1.0}) {
    points.emplace_back(s, 1.0), points.emplace_back(-1.0, s), points.emplace_back(s, -1.0);
    points.emplace_back(1.0, s);
  }
  for (const Vec2& x : points) {
    const auto lambda = coordinates(square, x, CoordinateKind::Wachspress);
    for (int k = 0; k < 4; ++k) {
      const Vec2& v = square.vertex(k);
      EXPECT_NEAR(at(lambda, square, k), (1 + x.x() * v.x()) * (1 + x.y() * v.y()) / 4, 1e-14)
          << x.transpose();
    }
  }
}

TEST(Barycentric, BothKindsAreTheLinearCoordinatesOnTheTriangle) {
  const Domain triangle(3);
  Eigen::Matrix3d m;
  for (int k = 0; k < 3; ++k) m.col(k) << triangle.vertex(k), 1.0;
  for (const Vec2& x : random_interior_points(triangle, 200, 11)) {
    const Eigen::Vector3d linear = m.partialPivLu().solve(Eigen::Vector3d(x.x(), x.y(), 1.0));
    for (CoordinateKind kind : kKinds) {
      const auto lambda = coordinates(triangle, x, kind);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(at(lambda, triangle, k), linear[k], 1e-14);
    }
  }
}

TEST(Barycentric, MeanValueDiffersFromWachspressForFiveOrMoreSides) {
  for (int n = 4; n <= 16; ++n) {
    const Domain domain(n);
    double largest = 0.0;
    for (const Vec2& x : random_interior_points(domain, 100, 23)) {
      const auto w = coordinates(domain, x, CoordinateKind::Wachspress);
      const auto m = coordinates(domain, x, CoordinateKind::MeanValue);
      for (std::size_t k = 0; k < w.size(); ++k) largest = std::max(largest, std::abs(w[k] - m[k]));
    }
    EXPECT_GT(largest, 1e-3) << "n=" << n;
  }
}

}  // namespace
}  // namespace isopatch
