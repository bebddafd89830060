#include "render/rasterizer.hpp"

#include <algorithm>
#include <cmath>

namespace isopatch::render {
namespace {

// Sign of which side of the line a->b the point (x, y) lies on, times the length of a->b.
double edge_function(const ScreenPoint& a, const ScreenPoint& b, double x, double y) {
  return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
}

// The range of sample indices whose centres (i + 0.5) lie in [lo, hi], clipped to [0, size).
std::pair<int, int> sample_range(double lo, double hi, int size) {
  const double first = std::max(0.0, std::ceil(lo - 0.5));
  const double last = std::min(static_cast<double>(size - 1), std::floor(hi - 0.5));
  if (!(first <= last)) return {0, -1};
  return {static_cast<int>(first), static_cast<int>(last)};
}

}  // namespace

DepthBuffer::DepthBuffer(int width_, int height_)
    : width(width_),
      height(height_),
      depth(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_),
            std::numeric_limits<float>::infinity()),
      triangle(depth.size(), kNoTriangle) {}

double signed_area(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c) {
  return edge_function(a, b, c.x, c.y);
}

void rasterize(const std::vector<Triangle>& triangles, const std::vector<ScreenPoint>& screen,
               const Camera& camera, DepthBuffer& buffer) {
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const ScreenPoint& a = screen[triangles[t][0]];
    const ScreenPoint& b = screen[triangles[t][1]];
    const ScreenPoint& c = screen[triangles[t][2]];
    const double area = signed_area(a, b, c);
    if (area == 0.0 || !std::isfinite(area)) continue;  // seen edge-on: covers no area
    const auto [x0, x1] = sample_range(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), buffer.width);
    const auto [y0, y1] = sample_range(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), buffer.height);
    const double inverse_area = 1.0 / area;
    const double qa = camera.interpolation_weight(a.depth);
    const double qb = camera.interpolation_weight(b.depth);
    const double qc = camera.interpolation_weight(c.depth);
    for (int y = y0; y <= y1; ++y) {
      const double py = y + 0.5;
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5;
        // Barycentric coordinates; dividing by the signed area makes them orientation-independent.
        const double ba = edge_function(b, c, px, py) * inverse_area;
        if (ba < 0.0) continue;
        const double bb = edge_function(c, a, px, py) * inverse_area;
        if (bb < 0.0) continue;
        const double bc = edge_function(a, b, px, py) * inverse_area;
        if (bc < 0.0) continue;
        const double weight = ba * qa + bb * qb + bc * qc;
        const double depth = (ba * qa * a.depth + bb * qb * b.depth + bc * qc * c.depth) / weight;
        const std::size_t i = buffer.index(x, y);
        if (depth < static_cast<double>(buffer.depth[i])) {
          buffer.depth[i] = static_cast<float>(depth);
          buffer.triangle[i] = static_cast<std::uint32_t>(t);
        }
      }
    }
  }
}

std::array<double, 3> interpolation_weights(const std::array<ScreenPoint, 3>& corners, double x, double y,
                                            const Camera& camera) {
  const auto& [a, b, c] = corners;
  const double area = signed_area(a, b, c);
  std::array<double, 3> w = {edge_function(b, c, x, y) / area * camera.interpolation_weight(a.depth),
                             edge_function(c, a, x, y) / area * camera.interpolation_weight(b.depth),
                             edge_function(a, b, x, y) / area * camera.interpolation_weight(c.depth)};
  const double sum = w[0] + w[1] + w[2];
  for (double& wi : w) wi /= sum;
  return w;
}

void draw_segment(Image& canvas, const DepthBuffer& buffer, const ScreenPoint& a, const ScreenPoint& b,
                  const Camera& camera, double width, double bias, Rgb colour) {
  const double radius = 0.5 * width;
  const auto [x0, x1] = sample_range(std::min(a.x, b.x) - radius, std::max(a.x, b.x) + radius, buffer.width);
  const auto [y0, y1] = sample_range(std::min(a.y, b.y) - radius, std::max(a.y, b.y) + radius, buffer.height);
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  const double qa = camera.interpolation_weight(a.depth);
  const double qb = camera.interpolation_weight(b.depth);
  for (int y = y0; y <= y1; ++y) {
    const double py = y + 0.5;
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5;
      // The nearest point of the segment, at screen parameter s.
      const double s =
          length2 > 0.0 ? std::clamp(((px - a.x) * dx + (py - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
      const double ex = a.x + s * dx - px;
      const double ey = a.y + s * dy - py;
      if (ex * ex + ey * ey > radius * radius) continue;
      const double depth = ((1.0 - s) * qa * a.depth + s * qb * b.depth) / ((1.0 - s) * qa + s * qb);
      if (depth <= static_cast<double>(buffer.depth[buffer.index(x, y)]) + bias) canvas.set(x, y, colour);
    }
  }
}

}  // namespace isopatch::render
