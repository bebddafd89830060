// The built-in 5x7 font of the legend and caption.
#include <isopatch/render.hpp>

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "render/font.hpp"

namespace isopatch {
namespace {

std::vector<bool> bitmap(char c) {
  std::vector<bool> bits;
  for (int row = 0; row < render::kGlyphHeight; ++row)
    for (int column = 0; column < render::kGlyphWidth; ++column)
      bits.push_back(render::glyph_pixel(c, column, row));
  return bits;
}

int ink(const std::vector<bool>& bits) {
  int n = 0;
  for (const bool b : bits) n += b ? 1 : 0;
  return n;
}

TEST(Font, CoversWhatLabelsNeedWithDistinctGlyphs) {
  const std::string needed = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ-+.,:=_()/?%";
  std::set<std::vector<bool>> seen;
  for (const char c : needed) {
    EXPECT_TRUE(render::has_glyph(c)) << c;
    EXPECT_GT(ink(bitmap(c)), 0) << c;
    EXPECT_TRUE(seen.insert(bitmap(c)).second) << c << " looks like another glyph";
  }
  EXPECT_TRUE(render::has_glyph(' '));
  EXPECT_EQ(ink(bitmap(' ')), 0);
  EXPECT_TRUE(render::has_glyph('e'));  // lower case drawn as upper case
  EXPECT_EQ(bitmap('e'), bitmap('E'));
  EXPECT_FALSE(render::has_glyph('@'));
  EXPECT_EQ(bitmap('@'), bitmap('?'));
}

TEST(Font, TextWidthAndScaledDrawing) {
  EXPECT_EQ(render::text_width("", 3), 0);
  EXPECT_EQ(render::text_width("7", 1), 5);
  EXPECT_EQ(render::text_width("-0.25", 2), (5 * 6 - 1) * 2);

  const Rgb ink_colour{0, 0, 0};
  Image image(40, 20, Rgb{255, 255, 255});
  render::draw_text(image, 2, 3, "8", 2, ink_colour);
  int drawn = 0, outside = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) {
      if (!(image.at(x, y) == ink_colour)) continue;
      ++drawn;
      if (x < 2 || x >= 2 + 10 || y < 3 || y >= 3 + 14) ++outside;
    }
  EXPECT_EQ(drawn, 4 * ink(bitmap('8')));  // every font pixel becomes a 2x2 block
  EXPECT_EQ(outside, 0);
  render::draw_text(image, 35, 15, "888", 3, ink_colour);  // overhanging text is clipped, not a crash
}

}  // namespace
}  // namespace isopatch
