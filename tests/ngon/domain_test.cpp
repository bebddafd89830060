#include "ngon/domain.hpp"

#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <cmath>

namespace isopatch {
namespace {

TEST(Domain, RejectsSideCountsOutsideThreeToSixteen) {
  for (int n : {-1, 0, 1, 2, 17, 100}) EXPECT_THROW(Domain{n}, InputError) << n;
  for (int n = 3; n <= 16; ++n) EXPECT_EQ(Domain(n).sides(), n);
}

TEST(Domain, IsARegularCounterClockwisePolygon) {
  for (int n = 3; n <= 16; ++n) {
    const Domain domain(n);
    ASSERT_EQ(domain.vertices().size(), static_cast<std::size_t>(n));
    const double side = (domain.vertex(1) - domain.vertex(0)).norm();
    const double radius = domain.vertex(0).norm();
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR((domain.vertex(k + 1) - domain.vertex(k)).norm(), side, 1e-14) << n << " " << k;
      EXPECT_NEAR(domain.vertex(k).norm(), radius, 1e-14);
      // Every turn is to the left: convex and counter-clockwise.
      EXPECT_GT(cross(domain.vertex(k + 1) - domain.vertex(k), domain.vertex(k + 2) - domain.vertex(k + 1)),
                0.5 * side * side * std::sin(2.0 * std::numbers::pi / n));
    }
    if (n != 4) {
      EXPECT_NEAR(radius, 1.0, 1e-15);
      EXPECT_EQ(domain.vertex(0), Vec2(1.0, 0.0));
    }
  }
}

TEST(Domain, SquareIsAxisAlignedAndExact) {
  const Domain square(4);
  EXPECT_EQ(square.vertex(0), Vec2(1, 1));
  EXPECT_EQ(square.vertex(1), Vec2(-1, 1));
  EXPECT_EQ(square.vertex(2), Vec2(-1, -1));
  EXPECT_EQ(square.vertex(3), Vec2(1, -1));
}

TEST(Domain, IndicesWrapBothWays) {
  const Domain domain(5);
  EXPECT_EQ(domain.wrap(-1), 4);
  EXPECT_EQ(domain.wrap(5), 0);
  EXPECT_EQ(domain.wrap(-11), 4);
  EXPECT_EQ(domain.vertex(-1), domain.vertex(4));
  EXPECT_EQ(domain.vertex(7), domain.vertex(2));
}

TEST(Domain, SidePointFollowsTheConventionAndHitsCornersExactly) {
  for (int n = 3; n <= 16; ++n) {
    const Domain domain(n);
    for (int k = 0; k < n; ++k) {
      EXPECT_EQ(domain.side_point(k, 0.0), domain.vertex(k));
      EXPECT_EQ(domain.side_point(k, 1.0), domain.vertex(k + 1));
      EXPECT_EQ(domain.side_point(k, 0, 7), domain.vertex(k));
      EXPECT_EQ(domain.side_point(k, 7, 7), domain.vertex(k + 1));
      const Vec2 mid = domain.side_point(k, 0.25);
      EXPECT_LT((mid - (0.75 * domain.vertex(k) + 0.25 * domain.vertex(k + 1))).norm(), 1e-15);
      EXPECT_EQ(domain.side_point(k, 3, 12), domain.side_point(k, 0.25));
      EXPECT_EQ(domain.side_point(k + n, 0.25), domain.side_point(k, 0.25));
    }
  }
}

}  // namespace
}  // namespace isopatch
