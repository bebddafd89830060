// The Image value type of render.hpp.
#include <isopatch/error.hpp>
#include <isopatch/render.hpp>

#include <cassert>

namespace isopatch {

Image::Image(int width, int height, Rgb fill) : width_(width), height_(height) {
  if (width < 1 || height < 1)
    throw InputError("image size " + std::to_string(width) + "x" + std::to_string(height) + " is empty");
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  bytes_.resize(3 * count);
  for (std::size_t i = 0; i < count; ++i) {
    bytes_[3 * i] = fill.r;
    bytes_[3 * i + 1] = fill.g;
    bytes_[3 * i + 2] = fill.b;
  }
}

Rgb Image::at(int x, int y) const {
  assert(x >= 0 && x < width_ && y >= 0 && y < height_);
  const std::size_t i =
      3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x));
  return Rgb{bytes_[i], bytes_[i + 1], bytes_[i + 2]};
}

void Image::set(int x, int y, Rgb colour) {
  if (x < 0 || x >= width_ || y < 0 || y >= height_) return;
  const std::size_t i =
      3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x));
  bytes_[i] = colour.r;
  bytes_[i + 1] = colour.g;
  bytes_[i + 2] = colour.b;
}

}  // namespace isopatch
