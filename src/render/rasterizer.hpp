#pragma once
// Visibility for the renderer: triangles into a depth buffer that remembers the nearest triangle of
// every sample, perspective-correct interpolation weights, and depth-tested line segments.

#include <isopatch/mesh.hpp>
#include <isopatch/render.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "render/camera.hpp"

namespace isopatch::render {

inline constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();

/// One depth and one triangle index per sample (pixel of the supersampled canvas), row 0 at the top.
struct DepthBuffer {
  DepthBuffer(int width_, int height_);
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  }

  int width = 0;
  int height = 0;
  std::vector<float> depth;             ///< +infinity where no triangle covers the sample
  std::vector<std::uint32_t> triangle;  ///< kNoTriangle where no triangle covers the sample
};

/// Twice the signed area of the projected triangle; negative when it is counter-clockwise seen by the
/// viewer (front-facing), since pixel rows go down.
double signed_area(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c);

/// Rasterizes every triangle of `screen` positions (one per mesh vertex) into `buffer`: a sample is
/// covered when its centre lies inside or on the triangle, and keeps the nearest triangle.
void rasterize(const std::vector<Triangle>& triangles, const std::vector<ScreenPoint>& screen,
               const Camera& camera, DepthBuffer& buffer);

/// Perspective-correct weights (summing to 1) of the three corners at pixel position (x, y), for
/// interpolating any per-vertex quantity. \pre the projected triangle is not degenerate.
std::array<double, 3> interpolation_weights(const std::array<ScreenPoint, 3>& corners, double x, double y,
                                            const Camera& camera);

/// Draws the segment a-b, `width` pixels wide, onto `canvas` (same size as `buffer`) wherever it is
/// not behind the surface: a sample is painted when the segment's depth there is at most the buffer's
/// depth plus `bias`.
void draw_segment(Image& canvas, const DepthBuffer& buffer, const ScreenPoint& a, const ScreenPoint& b,
                  const Camera& camera, double width, double bias, Rgb colour);

}  // namespace isopatch::render
