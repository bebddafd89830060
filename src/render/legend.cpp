#include "render/legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/colour_map.hpp"
#include "render/font.hpp"
#include "render/shading.hpp"

namespace isopatch::render {
namespace {

const Rgb kInk{26, 26, 30};

std::string format_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

struct Layout {
  int scale;
  int margin;
  int bar_width;
  int gap;
  int labels_width;
  int strip;
};

Layout layout(int width, int height, const Legend& legend) {
  Layout l{};
  l.scale = text_scale(width, height);
  l.margin = 8 * l.scale;
  l.bar_width = 12 * l.scale;
  l.gap = 6 * l.scale;
  for (const std::string& label : legend_labels(legend))
    l.labels_width = std::max(l.labels_width, text_width(label, l.scale));
  l.strip = l.margin + l.bar_width + l.gap + l.labels_width + l.margin;
  return l;
}

}  // namespace

int text_scale(int width, int height) {
  return 1 + std::min(width, height) / 400;
}

std::vector<std::string> legend_labels(const Legend& legend) {
  if (legend.diverging) return {format_number(legend.range), "0", format_number(-legend.range)};
  return {format_number(legend.range), format_number(0.5 * legend.range), "0"};
}

int legend_width(int width, int height, const Legend& legend) {
  return layout(width, height, legend).strip;
}

void draw_legend(Image& image, const Legend& legend) {
  const Layout l = layout(image.width(), image.height(), legend);
  const int x0 = image.width() - l.strip + l.margin;
  const int x1 = x0 + l.bar_width;  // exclusive
  const int top = static_cast<int>(std::lround(0.2 * image.height()));
  const int bottom = std::max(top + 1, static_cast<int>(std::lround(0.8 * image.height())));  // exclusive
  const double span = bottom - top;
  for (int y = top; y < bottom; ++y) {
    const double s = (y + 0.5 - top) / span;  // 0 at the top, 1 at the bottom
    const Rgb c = to_rgb8(legend.diverging ? diverging_colour(1.0 - 2.0 * s) : sequential_colour(1.0 - s));
    for (int x = x0; x < x1; ++x) image.set(x, y, c);
  }
  for (int x = x0 - 1; x <= x1; ++x) {
    image.set(x, top - 1, kInk);
    image.set(x, bottom, kInk);
  }
  for (int y = top - 1; y <= bottom; ++y) {
    image.set(x0 - 1, y, kInk);
    image.set(x1, y, kInk);
  }
  const std::vector<std::string> labels = legend_labels(legend);
  const int ticks[3] = {top, (top + bottom) / 2, bottom - 1};
  for (std::size_t i = 0; i < labels.size(); ++i) {
    for (int x = x1; x < x1 + l.gap / 2; ++x)
      for (int dy = 0; dy < l.scale; ++dy) image.set(x, ticks[i] + dy - l.scale / 2, kInk);
    const int text_top = ticks[i] - kGlyphHeight * l.scale / 2;
    draw_text(image, x1 + l.gap, text_top, labels[i], l.scale, kInk);
  }
}

}  // namespace isopatch::render
