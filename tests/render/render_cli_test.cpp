// End-to-end tests of `isopatch render`: a mesh written by `isopatch mesh` drawn into PNG files that
// are read back with an independent decoder.
#include <isopatch/curvature.hpp>
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/render.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "error_report.hpp"
#include "png_reader.hpp"
#include "render_fixtures.hpp"
#include "run_command.hpp"

namespace isopatch {
namespace {

const std::string kCli = ISOPATCH_CLI;

// A marching-cubes sphere, written once per test folder.
std::string sphere_mesh(const std::filesystem::path& dir) {
  const auto path = dir / "sphere.ply";
  const auto r = test::run_command(kCli + " mesh sphere --method mc --grid 24 -q -o " + path.string(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return path.string();
}

// Pixels that are not the corner's colour (the background).
int drawn_pixels(const Image& image) {
  return test::count_other_than(image, image.at(0, 0));
}

TEST(RenderCli, DrawsEveryGeometricView) {
  const auto dir = test::scratch_dir("render_cli_views");
  const std::string mesh = sphere_mesh(dir);
  for (const std::string show : {"shaded", "wireframe", "isophotes"}) {
    const auto out = dir / (show + ".png");
    const auto r = test::run_command(
        kCli + " render " + mesh + " -o " + out.string() + " --show " + show + " --size 320x240 --view 40,20",
        dir);
    ASSERT_EQ(r.exit_code, 0) << show << ": " << r.err;
    EXPECT_NE(r.out.find("wrote"), std::string::npos);
    const test::DecodedPng png = test::read_png(out.string());
    ASSERT_TRUE(png.ok) << show;
    EXPECT_EQ(png.image.width(), 320);
    EXPECT_EQ(png.image.height(), 240);
    EXPECT_GT(drawn_pixels(png.image), 20000) << show;  // the sphere spans most of the height
  }
}

TEST(RenderCli, CurvatureFromTheSurfaceOrFromStoredAttributes) {
  const auto dir = test::scratch_dir("render_cli_fields");
  const std::string mesh = sphere_mesh(dir);
  const auto computed = dir / "h.png";
  auto r = test::run_command(kCli + " render " + mesh + " -o " + computed.string() +
                                 " --show mean-curvature --surface sphere --size 300x200 --range 2",
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("mean_curvature"), std::string::npos);
  const test::DecodedPng png = test::read_png(computed.string());
  ASSERT_TRUE(png.ok);
  EXPECT_EQ(png.image.width(), 300);
  EXPECT_GT(drawn_pixels(png.image), 10000);

  // Attributes stored in the file are used without --surface.
  Mesh with_fields = read_mesh(mesh);
  with_fields.set_attribute("distance", std::vector<float>(with_fields.vertex_count(), 0.01f));
  const auto stored = dir / "stored.ply";
  write_mesh(with_fields, stored.string());
  const auto error = dir / "error.png";
  r = test::run_command(kCli + " render " + stored.string() + " -o " + error.string() + " --show error", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("0 .. 0.01"), std::string::npos) << r.out;
  EXPECT_TRUE(test::read_png(error.string()).ok);
}

TEST(RenderCli, BadInputGivesOneLineAndTheRightExitCode) {
  const auto dir = test::scratch_dir("render_cli_bad");
  const std::string mesh = sphere_mesh(dir);
  const std::string png = (dir / "x.png").string();
  struct Case {
    std::string args;
    ErrorKind kind;
  };
  const Case cases[] = {
      {mesh + " -o " + png + " --show mean-curvature", ErrorKind::InvalidArgument},  // no field, no surface
      {mesh + " -o " + png + " --show sparkles", ErrorKind::InvalidArgument},
      {mesh + " -o " + png + " --size 0x100", ErrorKind::InvalidArgument},
      {mesh + " -o " + png + " --size 9000x100", ErrorKind::InvalidArgument},
      {mesh + " -o " + png + " --size big", ErrorKind::InvalidArgument},
      {mesh + " -o " + png + " --view 30", ErrorKind::InvalidArgument},
      {mesh + " -o " + png + " --show shaded --range 1", ErrorKind::InvalidArgument},
      {mesh + " -o " + png + " --show field", ErrorKind::InvalidArgument},
      {mesh + " -o " + png + " --show error --surface sphere --range -1", ErrorKind::InvalidArgument},
      {mesh + " -o " + png + " --show error --surface sphear", ErrorKind::UnknownSurface},
      {mesh + " -o " + (dir / "x.jpg").string(), ErrorKind::Io},
      {mesh + " -o " + (dir / "no_such_folder" / "x.png").string(), ErrorKind::Io},
      {(dir / "missing.ply").string() + " -o " + png, ErrorKind::Io},
  };
  for (const Case& c : cases) {
    const auto r = test::run_command(kCli + " render " + c.args, dir);
    EXPECT_EQ(r.exit_code, cli::exit_code(c.kind)) << c.args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << "\n" << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(png));
}

}  // namespace
}  // namespace isopatch
