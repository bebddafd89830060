#include "png_reader.hpp"

// stb's decoder is third-party code inlined here; GCC's flow analysis flags its unchecked allocations.
#pragma GCC diagnostic ignored "-Wnull-dereference"
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace isopatch::test {

DecodedPng read_png(const std::string& path) {
  DecodedPng result;
  int width = 0, height = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &width, &height, &result.channels, 3);
  if (pixels == nullptr) return result;
  result.ok = true;
  result.image = Image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* p = pixels + 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                             static_cast<std::size_t>(x));
      result.image.set(x, y, Rgb{p[0], p[1], p[2]});
    }
  stbi_image_free(pixels);
  return result;
}

}  // namespace isopatch::test
