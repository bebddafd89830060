// write_png: the file decodes (with an independent decoder) to the same size and pixels.
#include <isopatch/error.hpp>
#include <isopatch/render.hpp>

#include <gtest/gtest.h>

#include <filesystem>

#include "png_reader.hpp"
#include "render_fixtures.hpp"
#include "run_command.hpp"

namespace isopatch {
namespace {

TEST(Png, WrittenPictureReadsBackExactly) {
  const auto dir = test::scratch_dir("render_png");
  Image image(37, 21, Rgb{10, 20, 30});
  image.set(0, 0, Rgb{255, 0, 0});
  image.set(36, 20, Rgb{0, 255, 0});
  image.set(5, 17, Rgb{1, 2, 3});
  const std::string path = (dir / "small.png").string();
  write_png(image, path);
  const test::DecodedPng png = test::read_png(path);
  ASSERT_TRUE(png.ok);
  EXPECT_EQ(png.channels, 3);
  ASSERT_EQ(png.image.width(), 37);
  ASSERT_EQ(png.image.height(), 21);
  EXPECT_EQ(png.image.bytes(), image.bytes());
  EXPECT_EQ(png.image.at(36, 20), (Rgb{0, 255, 0}));
}

TEST(Png, RenderedMeshRoundTrips) {
  const auto dir = test::scratch_dir("render_png_mesh");
  RenderOptions o;
  o.width = 120;
  o.height = 90;
  const Image image = render_mesh(test::uv_sphere(1.0, 8, 16), o);
  const std::string path = (dir / "sphere.png").string();
  write_png(image, path);
  const test::DecodedPng png = test::read_png(path);
  ASSERT_TRUE(png.ok);
  EXPECT_EQ(png.image.bytes(), image.bytes());
}

TEST(Png, UnwritablePathIsAnIoError) {
  const auto dir = test::scratch_dir("render_png_bad");
  const Image image(4, 4);
  EXPECT_THROW(write_png(image, (dir / "missing_folder" / "x.png").string()), IoError);
  EXPECT_THROW(write_png(image, dir.string()), IoError);  // a folder
  EXPECT_THROW(write_png(Image{}, (dir / "empty.png").string()), InputError);
}

TEST(Png, ImageRejectsEmptySizes) {
  EXPECT_THROW(Image(0, 5), InputError);
  EXPECT_THROW(Image(5, -1), InputError);
}

}  // namespace
}  // namespace isopatch
