// write_png with stb_image_write (Debian's libstb-dev). The implementation is compiled here, in this
// one translation unit, with static linkage so that it cannot clash with a user's own copy of stb.
// stb only encodes (into memory); the file is written here so that every failure is reported.
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/render.hpp>

// stb's encoder gets inlined into write_png, where GCC's flow analysis flags allocations that stb
// leaves unchecked; those warnings are about third-party code, so they are silenced for this file.
#pragma GCC diagnostic ignored "-Wnull-dereference"
#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace isopatch {
namespace {

void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

void write_png(const Image& image, const std::string& path) {
  if (image.width() < 1 || image.height() < 1)
    throw InputError("cannot write an empty image to '" + path + "'");
  std::string encoded;
  if (stbi_write_png_to_func(append_bytes, &encoded, image.width(), image.height(), 3, image.bytes().data(),
                             3 * image.width()) == 0)
    throw IoError("cannot encode '" + path + "' as PNG");
  write_whole_file(path, encoded);
}

}  // namespace isopatch
