// A cap's side divided at sizes graded between its ends (planar/graded_division.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "planar/graded_division.hpp"

namespace isopatch::planar {
namespace {

TEST(GradedDivision, EqualSizesGiveEqualPieces) {
  const std::vector<double> t = graded_division(1.0, 0.2, 0.2);
  ASSERT_EQ(t.size(), 4u);
  for (std::size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(t[k], 0.2 * static_cast<double>(k + 1), 1e-15);
  EXPECT_TRUE(graded_division(0.1, 0.2, 0.2).empty());  // shorter than one piece: whole
}

TEST(GradedDivision, PiecesGrowFromTheFineEndToTheCoarseOne) {
  const double length = 0.6, fine = 0.04, coarse = 0.15;
  const std::vector<double> t = graded_division(length, fine, coarse);
  // n = the integral of 1 / s, rounded: 0.6 ln(0.15 / 0.04) / 0.11 = 7.2.
  ASSERT_EQ(t.size() + 1, 7u);
  std::vector<double> pieces;
  double last = 0.0;
  for (double x : t) {
    pieces.push_back((x - last) * length);
    last = x;
  }
  pieces.push_back((1.0 - last) * length);
  for (std::size_t k = 1; k < pieces.size(); ++k) EXPECT_GT(pieces[k], pieces[k - 1]);
  EXPECT_NEAR(pieces.front(), fine, 0.3 * fine);
  EXPECT_NEAR(pieces.back(), coarse, 0.3 * coarse);
  // The other way round: the same points mirrored.
  const std::vector<double> back = graded_division(length, coarse, fine);
  ASSERT_EQ(back.size(), t.size());
  for (std::size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(back[k], 1.0 - t[t.size() - 1 - k], 1e-12);
}

}  // namespace
}  // namespace isopatch::planar
