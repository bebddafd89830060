#include "render/font.hpp"

#include <cctype>
#include <string_view>
#include <utility>

namespace isopatch::render {
namespace {

struct Glyph {
  char c;
  // Seven rows of five columns, top row first, separated by spaces; '#' is ink.
  std::string_view rows;
};

constexpr Glyph kGlyphs[] = {
    {' ', "..... ..... ..... ..... ..... ..... ....."}, {'0', ".###. #...# #..## #.#.# ##..# #...# .###."},
    {'1', "..#.. .##.. ..#.. ..#.. ..#.. ..#.. .###."}, {'2', ".###. #...# ....# ...#. ..#.. .#... #####"},
    {'3', "##### ...#. ..#.. ...#. ....# #...# .###."}, {'4', "...#. ..##. .#.#. #..#. ##### ...#. ...#."},
    {'5', "##### #.... ####. ....# ....# #...# .###."}, {'6', "..##. .#... #.... ####. #...# #...# .###."},
    {'7', "##### ....# ...#. ..#.. .#... .#... .#..."}, {'8', ".###. #...# #...# .###. #...# #...# .###."},
    {'9', ".###. #...# #...# .#### ....# ...#. .##.."}, {'A', ".###. #...# #...# ##### #...# #...# #...#"},
    {'B', "####. #...# #...# ####. #...# #...# ####."}, {'C', ".###. #...# #.... #.... #.... #...# .###."},
    {'D', "####. #...# #...# #...# #...# #...# ####."}, {'E', "##### #.... #.... ####. #.... #.... #####"},
    {'F', "##### #.... #.... ####. #.... #.... #...."}, {'G', ".###. #...# #.... #.### #...# #...# .####"},
    {'H', "#...# #...# #...# ##### #...# #...# #...#"}, {'I', ".###. ..#.. ..#.. ..#.. ..#.. ..#.. .###."},
    {'J', "..### ...#. ...#. ...#. ...#. #..#. .##.."}, {'K', "#...# #..#. #.#.. ##... #.#.. #..#. #...#"},
    {'L', "#.... #.... #.... #.... #.... #.... #####"}, {'M', "#...# ##.## #.#.# #.#.# #...# #...# #...#"},
    {'N', "#...# #...# ##..# #.#.# #..## #...# #...#"}, {'O', ".###. #...# #...# #...# #...# #...# .###."},
    {'P', "####. #...# #...# ####. #.... #.... #...."}, {'Q', ".###. #...# #...# #...# #.#.# #..#. .##.#"},
    {'R', "####. #...# #...# ####. #.#.. #..#. #...#"}, {'S', ".#### #.... #.... .###. ....# ....# ####."},
    {'T', "##### ..#.. ..#.. ..#.. ..#.. ..#.. ..#.."}, {'U', "#...# #...# #...# #...# #...# #...# .###."},
    {'V', "#...# #...# #...# #...# #...# .#.#. ..#.."}, {'W', "#...# #...# #...# #.#.# #.#.# #.#.# .#.#."},
    {'X', "#...# #...# .#.#. ..#.. .#.#. #...# #...#"}, {'Y', "#...# #...# .#.#. ..#.. ..#.. ..#.. ..#.."},
    {'Z', "##### ....# ...#. ..#.. .#... #.... #####"}, {'-', "..... ..... ..... .###. ..... ..... ....."},
    {'+', "..... ..#.. ..#.. ##### ..#.. ..#.. ....."}, {'.', "..... ..... ..... ..... ..... .##.. .##.."},
    {',', "..... ..... ..... ..... .##.. ..#.. .#..."}, {':', "..... .##.. .##.. ..... .##.. .##.. ....."},
    {'=', "..... ..... ##### ..... ##### ..... ....."}, {'_', "..... ..... ..... ..... ..... ..... #####"},
    {'(', "...#. ..#.. .#... .#... .#... ..#.. ...#."}, {')', ".#... ..#.. ...#. ...#. ...#. ..#.. .#..."},
    {'/', "....# ....# ...#. ..#.. .#... #.... #...."}, {'%', "##... ##..# ...#. ..#.. .#... #..## ...##"},
};

// Stands for every character without a glyph of its own.
constexpr Glyph kUnknown = {'?', ".###. #...# ....# ...#. ..#.. ..... ..#.."};

// Every glyph is well formed: seven rows of five cells, separated by single spaces.
constexpr bool glyphs_well_formed() {
  for (const Glyph& g : kGlyphs) {
    if (g.c == kUnknown.c) return false;
    if (g.rows.size() != kGlyphHeight * (kGlyphWidth + 1) - 1) return false;
    for (std::size_t i = 0; i < g.rows.size(); ++i) {
      const bool separator = i % (kGlyphWidth + 1) == kGlyphWidth;
      if (separator ? g.rows[i] != ' ' : (g.rows[i] != '#' && g.rows[i] != '.')) return false;
    }
  }
  return true;
}
static_assert(glyphs_well_formed());

// The glyph of c, and whether the font has one of its own.
std::pair<const Glyph&, bool> find_glyph(char c) {
  const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const Glyph& g : kGlyphs)
    if (g.c == upper) return {g, true};
  return {kUnknown, upper == kUnknown.c};
}

}  // namespace

bool has_glyph(char c) {
  return find_glyph(c).second;
}

bool glyph_pixel(char c, int column, int row) {
  const Glyph& g = find_glyph(c).first;
  return g.rows[static_cast<std::size_t>(row * (kGlyphWidth + 1) + column)] == '#';
}

int text_width(const std::string& text, int scale) {
  if (text.empty()) return 0;
  return (static_cast<int>(text.size()) * kGlyphAdvance - 1) * scale;
}

void draw_text(Image& image, int x, int y, const std::string& text, int scale, Rgb colour) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const int left = x + static_cast<int>(i) * kGlyphAdvance * scale;
    for (int row = 0; row < kGlyphHeight; ++row)
      for (int column = 0; column < kGlyphWidth; ++column) {
        if (!glyph_pixel(text[i], column, row)) continue;
        for (int dy = 0; dy < scale; ++dy)
          for (int dx = 0; dx < scale; ++dx)
            image.set(left + column * scale + dx, y + row * scale + dy, colour);
      }
  }
}

}  // namespace isopatch::render
