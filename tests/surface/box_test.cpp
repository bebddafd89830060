#include <isopatch/error.hpp>
#include <isopatch/geometry.hpp>

#include <gtest/gtest.h>

namespace isopatch {
namespace {

TEST(Box, ParsesSixNumbersAndRoundTrips) {
  const Box b = parse_box("-1.3,-1.2,-1.1,1.2,1.3,1.25");
  EXPECT_TRUE(b.valid());
  EXPECT_DOUBLE_EQ(b.lo.x(), -1.3);
  EXPECT_DOUBLE_EQ(b.hi.z(), 1.25);
  const Box c = parse_box(format_box(b));
  EXPECT_EQ(b.lo, c.lo);
  EXPECT_EQ(b.hi, c.hi);
  EXPECT_TRUE(parse_box(" -1, -1, -1, 1, 1, 1").valid());
}

TEST(Box, RejectsMalformedOrEmptyBoxes) {
  for (const char* text : {"", "1,2,3", "0,0,0,1,1,x", "0,0,0,1,1,1,1", "0,0,0,1,1,0", "1,0,0,0,1,1",
                           "0,0,0,1,1,nan", "0,0,0,1,1,inf", "0,,0,1,1,1"}) {
    EXPECT_THROW(parse_box(text), InputError) << text;
  }
}

TEST(Box, ContainsWithMargin) {
  const Box b{Vec3::Zero(), Vec3::Ones()};
  EXPECT_TRUE(b.contains(Vec3(0.5, 0.5, 0.5)));
  EXPECT_FALSE(b.contains(Vec3(1.1, 0.5, 0.5)));
  EXPECT_TRUE(b.contains(Vec3(1.1, 0.5, 0.5), 0.2));
}

}  // namespace
}  // namespace isopatch
