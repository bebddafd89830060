#pragma once
// The colour bar of the renderer's field modes: a vertical bar at the right of the picture with the
// range's end points and middle written beside it in the built-in font.

#include <isopatch/render.hpp>

#include <string>
#include <vector>

namespace isopatch::render {

struct Legend {
  bool diverging = true;  ///< [-range, range] on the diverging map, else [0, range] on the sequential
  double range = 1.0;
};

/// Size of a font pixel for a picture: 1 per whole 400 pixels of its smaller side, at least 1.
int text_scale(int width, int height);

/// The labels beside the bar, top to bottom ("%.3g" of the range, its middle and its bottom).
std::vector<std::string> legend_labels(const Legend& legend);

/// Width in pixels of the strip the legend occupies at the right of a width x height picture.
int legend_width(int width, int height, const Legend& legend);

/// Draws the legend into the strip of legend_width() pixels at the right of `image` (the strip's
/// background is left as it is). The bar spans the middle 60% of the height.
void draw_legend(Image& image, const Legend& legend);

}  // namespace isopatch::render
