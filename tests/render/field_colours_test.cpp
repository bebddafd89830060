// field_vertex_colours: the colours the field modes draw, in linear RGB. Checked against render_mesh
// itself: a sphere whose field is constant, lit with field_ambient = 1 (no shading), shows exactly the
// colour that field_vertex_colours gives, once turned back into sRGB.
#include <isopatch/error.hpp>
#include <isopatch/render.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "render_fixtures.hpp"

namespace isopatch {
namespace {

int to_srgb8(double linear) {
  const double c = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::lround(255.0 * c));
}

void expect_drawn_as(double value, RenderMode mode) {
  Mesh mesh = test::uv_sphere();
  mesh.set_attribute("f", std::vector<float>(mesh.vertex_count(), static_cast<float>(value)));
  RenderOptions o;
  o.mode = mode;
  o.field = "f";
  o.range = 2.0;
  o.legend = false;
  o.width = o.height = 64;
  o.lighting.field_ambient = 1.0;
  RenderInfo info;
  const std::vector<Colour> colours = field_vertex_colours(mesh, o, &info);
  ASSERT_EQ(colours.size(), mesh.vertex_count());
  EXPECT_EQ(info.range, 2.0);
  const Rgb drawn = render_mesh(mesh, o).at(32, 32);
  const Colour& c = colours.front();
  EXPECT_NEAR(to_srgb8(c.x()), drawn.r, 1) << value;
  EXPECT_NEAR(to_srgb8(c.y()), drawn.g, 1) << value;
  EXPECT_NEAR(to_srgb8(c.z()), drawn.b, 1) << value;
  for (const Colour& other : colours) EXPECT_EQ(other, c);
}

TEST(FieldColours, AreWhatTheFieldModesDraw) {
  for (const double v : {-3.0, -1.0, -0.4, 0.0, 0.7, 1.5, 2.0, 5.0})
    expect_drawn_as(v, RenderMode::ScalarField);
  for (const double v : {-1.5, 0.0, 0.3, 1.9}) expect_drawn_as(v, RenderMode::Error);
  expect_drawn_as(std::numeric_limits<double>::quiet_NaN(), RenderMode::ScalarField);
}

TEST(FieldColours, AreLinearAndUseTheRobustRange) {
  Mesh mesh = test::uv_sphere(1.0, 6, 8);
  RenderOptions o;
  o.mode = RenderMode::ScalarField;
  o.values.assign(mesh.vertex_count(), 0.0);
  o.values[0] = 1.0;  // white at 0, full red at the range
  o.values[1] = -1.0;
  o.values[2] = std::numeric_limits<double>::infinity();
  RenderInfo info;
  const std::vector<Colour> c = field_vertex_colours(mesh, o, &info);
  EXPECT_EQ(info.missing_values, 1u);
  EXPECT_EQ(info.range, 1.0);
  EXPECT_EQ(c[3], Colour(1, 1, 1));
  EXPECT_NEAR(c[0].y(), std::pow((0.09 + 0.055) / 1.055, 2.4), 1e-12) << "sRGB 0.09 in linear light";
  EXPECT_LT(c[1].x(), c[1].z());
  EXPECT_NEAR(c[2].x(), std::pow((0.55 + 0.055) / 1.055, 2.4), 1e-12) << "the missing colour";
}

TEST(FieldColours, RefuseWhatRenderMeshRefuses) {
  const Mesh mesh = test::uv_sphere(1.0, 6, 8);
  RenderOptions o;
  EXPECT_THROW(field_vertex_colours(mesh, o), InputError) << "not a field mode";
  o.mode = RenderMode::ScalarField;
  EXPECT_THROW(field_vertex_colours(mesh, o), InputError) << "no values";
  o.field = "nothing";
  EXPECT_THROW(field_vertex_colours(mesh, o), InputError);
  o.values.assign(3, 1.0);
  EXPECT_THROW(field_vertex_colours(mesh, o), InputError) << "wrong count";
  o.values.assign(mesh.vertex_count(), 1.0);
  o.range = -1.0;
  EXPECT_THROW(field_vertex_colours(mesh, o), InputError);
}

}  // namespace
}  // namespace isopatch
