#pragma once
// Reads a PNG back for the renderer's tests, with stb_image (an independent decoder).

#include <isopatch/render.hpp>

#include <string>

namespace isopatch::test {

struct DecodedPng {
  bool ok = false;
  int channels = 0;  ///< channels stored in the file
  Image image;       ///< the pixels as RGB
};

DecodedPng read_png(const std::string& path);

}  // namespace isopatch::test
