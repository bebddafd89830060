// Each mode of the renderer: something is drawn, fields are coloured as the maps say, the legend shows
// the range, wireframe only darkens, isophotes alternate.
#include <isopatch/error.hpp>
#include <isopatch/render.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "render/colour_map.hpp"
#include "render/legend.hpp"
#include "render/shading.hpp"
#include "render_fixtures.hpp"

namespace isopatch {
namespace {

std::vector<double> heights(const Mesh& mesh) {
  std::vector<double> z;
  for (const Vec3& p : mesh.positions) z.push_back(p.z());
  return z;
}

Rgb facing_colour(const Colour& base, const Lighting& light) {
  const Vec3 l = light.direction.normalized();
  return render::to_rgb8(base * (light.field_ambient + (1.0 - light.field_ambient) * std::max(0.0, l.z())));
}

TEST(RenderModes, EveryModeDrawsTheMesh) {
  const Mesh sphere = test::uv_sphere();
  for (const RenderMode mode : {RenderMode::Shaded, RenderMode::Wireframe, RenderMode::ScalarField,
                                RenderMode::Isophotes, RenderMode::Error}) {
    RenderOptions o;
    o.width = 400;
    o.height = 300;
    o.mode = mode;
    o.values = heights(sphere);
    const Image image = render_mesh(sphere, o);
    ASSERT_EQ(image.width(), 400);
    ASSERT_EQ(image.height(), 300);
    const Rgb background = render::to_rgb8(o.background);
    EXPECT_GT(test::count_other_than(image, background), 30000) << static_cast<int>(mode);
  }
}

TEST(RenderModes, FieldValuesAreColouredByTheMaps) {
  const Mesh square = test::square_facing_x();
  RenderOptions o;
  o.width = o.height = 400;
  o.azimuth = 0.0;
  o.elevation = 0.0;
  o.mode = RenderMode::ScalarField;
  o.range = 2.0;
  o.legend = false;
  for (const double v : {-2.0, -1.0, 0.0, 0.5, 2.0, 7.0}) {
    o.values.assign(4, v);
    const Image image = render_mesh(square, o);
    EXPECT_LE(test::channel_distance(image.at(200, 200),
                                     facing_colour(render::diverging_colour(v / 2.0), o.lighting)),
              1)
        << v;
  }
  o.mode = RenderMode::Error;
  for (const double v : {0.0, -1.0, 1.0, 3.0}) {
    o.values.assign(4, v);
    const Image image = render_mesh(square, o);
    EXPECT_LE(test::channel_distance(image.at(200, 200),
                                     facing_colour(render::sequential_colour(std::abs(v) / 2.0), o.lighting)),
              1)
        << v;
  }
  o.values.assign(4, std::nan(""));
  RenderInfo info;
  const Image image = render_mesh(square, o, &info);
  EXPECT_LE(test::channel_distance(image.at(200, 200), facing_colour(o.missing_colour, o.lighting)), 1);
  EXPECT_EQ(info.missing_values, 4u);
}

TEST(RenderModes, FieldFromAMeshAttribute) {
  Mesh square = test::square_facing_x();
  square.set_attribute("mean_curvature", {1.0f, 1.0f, 1.0f, 1.0f});
  RenderOptions o;
  o.width = o.height = 400;
  o.azimuth = 0.0;
  o.elevation = 0.0;
  o.mode = RenderMode::ScalarField;
  o.field = "mean_curvature";
  o.range = 1.0;
  const Image image = render_mesh(square, o);
  EXPECT_LE(
      test::channel_distance(image.at(150, 200), facing_colour(render::diverging_colour(1.0), o.lighting)),
      1);
}

TEST(RenderModes, DefaultRangeIsRobustAndExplicitRangeIsKept) {
  const Mesh sphere = test::uv_sphere();
  RenderOptions o;
  o.width = o.height = 200;
  o.mode = RenderMode::ScalarField;
  o.values = heights(sphere);
  RenderInfo info;
  render_mesh(sphere, o, &info);
  EXPECT_GT(info.range, 0.9);
  EXPECT_LE(info.range, 1.0);
  const double robust = info.range;
  o.values[7] = 1e6;  // one outlier does not stretch the map
  render_mesh(sphere, o, &info);
  EXPECT_DOUBLE_EQ(info.range, robust);
  o.range = 0.25;
  render_mesh(sphere, o, &info);
  EXPECT_EQ(info.range, 0.25);
}

TEST(RenderModes, AllZeroFieldStillHasAPositiveRange) {
  const Mesh sphere = test::uv_sphere(1.0, 6, 8);
  RenderOptions o;
  o.width = o.height = 100;
  o.mode = RenderMode::ScalarField;
  o.values.assign(sphere.vertex_count(), 0.0);
  RenderInfo info;
  render_mesh(sphere, o, &info);
  EXPECT_GT(info.range, 0.0);
}

TEST(RenderModes, LegendShowsTheColourBarAndLabels) {
  const Mesh sphere = test::uv_sphere();
  RenderOptions o;
  o.mode = RenderMode::ScalarField;
  o.values = heights(sphere);
  o.range = 1.5;
  const Image with = render_mesh(sphere, o);
  const render::Legend legend{true, 1.5};
  const int strip = render::legend_width(800, 800, legend);
  ASSERT_GT(strip, 30);
  ASSERT_LT(strip, 400);
  int ink = 0;
  for (int y = 0; y < 800; ++y)
    for (int x = 800 - strip; x < 800; ++x) ink += test::brightness(with.at(x, y)) < 150 ? 1 : 0;
  EXPECT_GT(ink, 200);  // frame, ticks and the three labels

  // The bar runs from the top colour of the map (+m) through white to the bottom one (-m).
  int bar_x = -1;
  for (int x = 800 - strip; x < 800 && bar_x < 0; ++x)
    if (test::channel_distance(with.at(x, 400), Rgb{255, 255, 255}) <= 3) bar_x = x;
  ASSERT_GE(bar_x, 0);
  const int top = 160, bottom = 640;
  EXPECT_LE(test::channel_distance(with.at(bar_x, top + 1), render::to_rgb8(render::diverging_colour(1.0))),
            4);
  EXPECT_LE(
      test::channel_distance(with.at(bar_x, bottom - 2), render::to_rgb8(render::diverging_colour(-1.0))), 4);

  // The mesh keeps clear of the legend's strip; without a legend it uses the whole width.
  const Rgb background = render::to_rgb8(o.background);
  EXPECT_EQ(with.at(800 - strip - 5, 400), background);
  o.legend = false;
  const Image without = render_mesh(sphere, o);
  EXPECT_NE(without.at(800 - strip - 5, 400), background);
}

TEST(RenderModes, ErrorLegendStartsAtZero) {
  const auto labels = render::legend_labels(render::Legend{false, 0.5});
  ASSERT_EQ(labels.size(), 3u);
  EXPECT_EQ(labels[0], "0.5");
  EXPECT_EQ(labels[1], "0.25");
  EXPECT_EQ(labels[2], "0");
  const auto diverging = render::legend_labels(render::Legend{true, 0.002});
  EXPECT_EQ(diverging[0], "0.002");
  EXPECT_EQ(diverging[2], "-0.002");
}

TEST(RenderModes, WireframeOnlyDarkens) {
  const Mesh sphere = test::uv_sphere(1.0, 12, 24);
  RenderOptions o;
  o.width = o.height = 400;
  const Image shaded = render_mesh(sphere, o);
  o.mode = RenderMode::Wireframe;
  const Image wire = render_mesh(sphere, o);
  int darker = 0, brighter = 0;
  for (int y = 0; y < 400; ++y)
    for (int x = 0; x < 400; ++x) {
      const int d = test::brightness(wire.at(x, y)) - test::brightness(shaded.at(x, y));
      darker += d < -30 ? 1 : 0;
      brighter += d > 0 ? 1 : 0;
    }
  EXPECT_EQ(brighter, 0);
  EXPECT_GT(darker, 3000);
}

TEST(RenderModes, IsophotesAlternateAcrossTheSphere) {
  const Mesh sphere = test::uv_sphere(1.0, 48, 96);
  RenderOptions o;
  o.width = o.height = 400;
  o.mode = RenderMode::Isophotes;
  const Image image = render_mesh(sphere, o);
  const Image shaded = [&] {
    RenderOptions s = o;
    s.mode = RenderMode::Shaded;
    return render_mesh(sphere, s);
  }();
  // Along the diagonal through the highlight, dark stripes (a fifth of the shaded brightness)
  // alternate with plain shading: the rings around the light's direction are crossed one by one.
  auto transitions = [&](const Image& stripes) {
    int n = 0;
    for (int i = 61; i < 340; ++i) {
      const bool a =
          3 * test::brightness(stripes.at(i - 1, i - 1)) < test::brightness(shaded.at(i - 1, i - 1));
      const bool b = 3 * test::brightness(stripes.at(i, i)) < test::brightness(shaded.at(i, i));
      n += a != b ? 1 : 0;
    }
    return n;
  };
  const int fine = transitions(image);
  EXPECT_GE(fine, 6);
  o.isophote_stripes = 2;  // fewer stripes, fewer transitions
  EXPECT_LT(transitions(render_mesh(sphere, o)), fine);
}

TEST(RenderModes, CaptionIsDrawnTopLeft) {
  const Mesh sphere = test::uv_sphere(0.5, 8, 12);
  RenderOptions o;
  o.width = o.height = 400;
  o.caption = "TORUS H";
  const Image with = render_mesh(sphere, o);
  o.caption.clear();
  const Image without = render_mesh(sphere, o);
  int ink_with = 0, ink_without = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 120; ++x) {
      ink_with += test::brightness(with.at(x, y)) < 150 ? 1 : 0;
      ink_without += test::brightness(without.at(x, y)) < 150 ? 1 : 0;
    }
  EXPECT_GT(ink_with, 40);
  EXPECT_EQ(ink_without, 0);
}

}  // namespace
}  // namespace isopatch
