#pragma once
// A tiny built-in 5x7 pixel font for the renderer's legend and caption: digits, A-Z (lower case is
// drawn as upper case), space and - + . , : = _ ( ) / ? %.

#include <isopatch/render.hpp>

#include <string>

namespace isopatch::render {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = 6;  ///< glyph width plus one column of spacing

/// True when the font has a glyph for `c` (case-insensitive).
bool has_glyph(char c);

/// Whether pixel (column, row) of the glyph of `c` is ink; row 0 is the top. Characters without a
/// glyph are drawn as '?'. \pre 0 <= column < kGlyphWidth, 0 <= row < kGlyphHeight.
bool glyph_pixel(char c, int column, int row);

/// Width in pixels of `text` drawn at `scale` (every font pixel a scale x scale block).
int text_width(const std::string& text, int scale);

/// Draws `text` with its top-left corner at (x, y); pixels outside the image are clipped.
void draw_text(Image& image, int x, int y, const std::string& text, int scale, Rgb colour);

}  // namespace isopatch::render
