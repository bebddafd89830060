// Colour maps and the robust range of the renderer's field modes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "render/colour_map.hpp"

namespace isopatch {
namespace {

double lightness(const Colour& c) {
  return 0.2126 * c.x() + 0.7152 * c.y() + 0.0722 * c.z();
}

TEST(ColourMap, DivergingEndpointsAndMiddle) {
  EXPECT_EQ(render::diverging_colour(0.0), Colour(1.0, 1.0, 1.0));
  const Colour blue = render::diverging_colour(-1.0);
  const Colour red = render::diverging_colour(1.0);
  EXPECT_GT(blue.z(), blue.x() + 0.3);
  EXPECT_GT(red.x(), red.z() + 0.3);
  EXPECT_EQ(render::diverging_colour(-4.0), blue);  // saturates
  EXPECT_EQ(render::diverging_colour(4.0), red);
  EXPECT_LT((render::diverging_colour(1e-9) - Colour(1, 1, 1)).norm(), 1e-6);  // continuous at 0
}

TEST(ColourMap, DivergingLightnessFallsAwayFromZero) {
  for (double t = 0.0; t < 1.0; t += 0.05) {
    EXPECT_GT(lightness(render::diverging_colour(t)), lightness(render::diverging_colour(t + 0.05)) - 1e-12)
        << t;
    EXPECT_GT(lightness(render::diverging_colour(-t)), lightness(render::diverging_colour(-t - 0.05)) - 1e-12)
        << t;
  }
}

TEST(ColourMap, SequentialRunsFromLightToDark) {
  const Colour low = render::sequential_colour(0.0);
  const Colour high = render::sequential_colour(1.0);
  EXPECT_GT(lightness(low), 0.9);
  EXPECT_LT(lightness(high), 0.2);
  EXPECT_GT(high.x(), high.z());  // dark red
  for (double t = 0.0; t < 1.0; t += 0.05)
    EXPECT_GT(lightness(render::sequential_colour(t)), lightness(render::sequential_colour(t + 0.05))) << t;
  EXPECT_EQ(render::sequential_colour(-1.0), low);
  EXPECT_EQ(render::sequential_colour(2.0), high);
  for (const double t : {0.0, 0.3, 0.7, 1.0})
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(render::sequential_colour(t)[k], 0.0);
      EXPECT_LE(render::sequential_colour(t)[k], 1.0);
    }
}

TEST(ColourMap, RobustMagnitudeIsANearestRankPercentileOfAbsoluteValues) {
  std::vector<double> values;
  for (int i = 1; i <= 100; ++i) values.push_back(i % 2 == 0 ? i : -i);
  EXPECT_EQ(render::robust_magnitude(values, 98.0), 98.0);
  EXPECT_EQ(render::robust_magnitude(values, 100.0), 100.0);
  EXPECT_EQ(render::robust_magnitude(values, 50.0), 50.0);
  EXPECT_EQ(render::robust_magnitude(values, 0.5), 1.0);
  values.push_back(std::nan(""));
  values.push_back(INFINITY);
  EXPECT_EQ(render::robust_magnitude(values, 98.0), 98.0);  // non-finite values are left out
  EXPECT_EQ(render::robust_magnitude({}, 98.0), 0.0);
  EXPECT_EQ(render::robust_magnitude({std::nan("")}, 98.0), 0.0);
}

}  // namespace
}  // namespace isopatch
