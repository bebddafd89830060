// The renderer against hand-computed values: the lighting formula on a flat face, back faces, hidden
// edges, picture sizes, determinism and the checks on its options.
#include <isopatch/error.hpp>
#include <isopatch/render.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "render/camera.hpp"
#include "render_fixtures.hpp"

namespace isopatch {
namespace {

// The documented formula of render.hpp for a face whose normal points at the viewer, n = (0, 0, 1).
Rgb expected_facing_colour(const Colour& base, const Lighting& light, bool specular) {
  const Vec3 l = light.direction / light.direction.norm();
  const Vec3 h = (l + Vec3(0, 0, 1)) / (l + Vec3(0, 0, 1)).norm();
  const double diffuse = light.ambient + light.diffuse * std::max(0.0, l.z());
  const double highlight = specular ? light.specular * std::pow(std::max(0.0, h.z()), light.shininess) : 0.0;
  auto channel = [&](double c) {
    return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(c * diffuse + highlight, 0.0, 1.0)));
  };
  return Rgb{channel(base.x()), channel(base.y()), channel(base.z())};
}

// A 400x400 view from +x, square on to test::square_facing_x().
RenderOptions facing_x() {
  RenderOptions o;
  o.width = 400;
  o.height = 400;
  o.azimuth = 0.0;
  o.elevation = 0.0;
  return o;
}

TEST(Render, FlatFaceTowardsTheCameraHasTheFormulasColour) {
  const Mesh square = test::square_facing_x();
  for (const CameraKind camera : {CameraKind::Perspective, CameraKind::Orthographic}) {
    RenderOptions o = facing_x();
    o.camera = camera;
    const Image image = render_mesh(square, o);
    const Rgb want = expected_facing_colour(o.surface_colour, o.lighting, true);
    for (const auto& [x, y] : {std::pair{200, 200}, std::pair{150, 160}, std::pair{260, 235}})
      EXPECT_LE(test::channel_distance(image.at(x, y), want), 1) << x << "," << y;
  }
}

TEST(Render, LightingParametersChangeTheColourAsTheFormulaSays) {
  RenderOptions o = facing_x();
  o.lighting.direction = Vec3(0.6, -0.2, 0.5);
  o.lighting.ambient = 0.1;
  o.lighting.diffuse = 0.6;
  o.lighting.specular = 0.4;
  o.lighting.shininess = 8.0;
  o.surface_colour = Colour(0.9, 0.3, 0.1);
  const Image image = render_mesh(test::square_facing_x(), o);
  EXPECT_LE(
      test::channel_distance(image.at(200, 200), expected_facing_colour(o.surface_colour, o.lighting, true)),
      1);
}

TEST(Render, BackFacesUseTheBackColourLitFromTheFront) {
  RenderOptions o = facing_x();
  o.azimuth = 180.0;  // behind the square, which faces +x
  const Image image = render_mesh(test::square_facing_x(), o);
  EXPECT_LE(
      test::channel_distance(image.at(200, 200), expected_facing_colour(o.back_colour, o.lighting, true)), 1);
}

TEST(Render, LookingStraightDownIsNotDegenerate) {
  Mesh square;  // facing +z
  square.positions = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  for (const double azimuth : {0.0, 37.0, -120.0}) {
    RenderOptions o;
    o.azimuth = azimuth;
    o.elevation = 90.0;
    o.width = o.height = 400;
    const Image image = render_mesh(square, o);
    EXPECT_LE(test::channel_distance(image.at(200, 200),
                                     expected_facing_colour(o.surface_colour, o.lighting, true)),
              1)
        << azimuth;
  }
}

TEST(Render, BackgroundAroundTheMesh) {
  const RenderOptions o = facing_x();
  const Image image = render_mesh(test::square_facing_x(), o);
  const Rgb background{static_cast<std::uint8_t>(std::lround(255 * o.background.x())),
                       static_cast<std::uint8_t>(std::lround(255 * o.background.y())),
                       static_cast<std::uint8_t>(std::lround(255 * o.background.z()))};
  EXPECT_EQ(image.at(0, 0), background);
  EXPECT_EQ(image.at(399, 399), background);
  EXPECT_EQ(image.at(200, 3), background);
}

TEST(Render, EdgesBehindTheSurfaceAreHidden) {
  // A dense grid at x = -0.5 behind a plain square at x = +0.5, seen from +x.
  Mesh mesh;
  const int n = 10;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) mesh.positions.emplace_back(-0.5, -1.0 + 2.0 * j / n, -1.0 + 2.0 * i / n);
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      mesh.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  const Mesh front = test::square_facing_x(0.5, 0.5);
  const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
  for (const Vec3& p : front.positions) mesh.positions.push_back(p);
  for (const Triangle& t : front.triangles)
    mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});

  RenderOptions o = facing_x();
  o.camera = CameraKind::Orthographic;
  o.mode = RenderMode::Wireframe;
  const Image image = render_mesh(mesh, o);
  const Rgb flat = expected_facing_colour(o.surface_colour, o.lighting, true);

  // Where the front square's corners land (same camera as render_mesh: the whole picture).
  const render::Camera camera = render::fit_camera(mesh.positions, o, render::Viewport{0, 0, 400, 400});
  const render::ScreenPoint lo = camera.project(front.positions[0]);  // bottom left
  const render::ScreenPoint hi = camera.project(front.positions[2]);  // top right, the diagonal's other end
  const int margin = 4;
  int inside = 0, wrong = 0;
  for (int y = static_cast<int>(hi.y) + margin; y < static_cast<int>(lo.y) - margin; ++y)
    for (int x = static_cast<int>(lo.x) + margin; x < static_cast<int>(hi.x) - margin; ++x) {
      // Skip the square's own diagonal edge.
      const double cross = (hi.x - lo.x) * (y + 0.5 - lo.y) - (hi.y - lo.y) * (x + 0.5 - lo.x);
      const double distance = std::abs(cross) / std::hypot(hi.x - lo.x, hi.y - lo.y);
      if (distance < margin) continue;
      ++inside;
      if (test::channel_distance(image.at(x, y), flat) > 1) ++wrong;
    }
  EXPECT_GT(inside, 5000);
  EXPECT_EQ(wrong, 0);
  // The grid's edges do show where nothing covers them.
  int dark = 0;
  for (int x = 0; x < static_cast<int>(lo.x) - margin; ++x)
    for (int y = 0; y < 400; ++y)
      dark += test::brightness(image.at(x, y)) < test::brightness(flat) - 150 ? 1 : 0;
  EXPECT_GT(dark, 250);
}

TEST(Render, PictureHasTheRequestedSizeAndCentresTheMesh) {
  RenderOptions o;
  o.width = 320;
  o.height = 200;
  const Image image = render_mesh(test::uv_sphere(), o);
  EXPECT_EQ(image.width(), 320);
  EXPECT_EQ(image.height(), 200);
  EXPECT_EQ(image.bytes().size(), 3u * 320u * 200u);
  const Rgb background = image.at(0, 0);
  EXPECT_NE(image.at(160, 100), background);
  EXPECT_EQ(image.at(20, 100), background);  // the sphere's outline spans the height, not the width
  EXPECT_EQ(image.at(300, 100), background);
}

TEST(Render, SameInputSamePixels) {
  RenderOptions o;
  o.width = o.height = 400;
  o.mode = RenderMode::Wireframe;
  const Mesh sphere = test::uv_sphere(0.8, 12, 20);
  const Image a = render_mesh(sphere, o);
  const Image b = render_mesh(sphere, o);
  EXPECT_EQ(a.bytes(), b.bytes());
}

TEST(Render, SupersamplingDoesNotChangeFlatRegions) {
  RenderOptions o = facing_x();
  o.supersampling = 1;
  const Image one = render_mesh(test::square_facing_x(), o);
  o.supersampling = 3;
  const Image three = render_mesh(test::square_facing_x(), o);
  EXPECT_EQ(one.at(200, 200), three.at(200, 200));
  EXPECT_EQ(one.at(0, 0), three.at(0, 0));
}

TEST(Render, RejectsBadOptionsAndMeshes) {
  const Mesh sphere = test::uv_sphere(1.0, 6, 8);
  auto rejects = [&](auto change) {
    RenderOptions o;
    change(o);
    EXPECT_THROW(render_mesh(sphere, o), InputError);
  };
  rejects([](RenderOptions& o) { o.width = 0; });
  rejects([](RenderOptions& o) { o.height = 0; });
  rejects([](RenderOptions& o) { o.width = kMaxImageSide + 1; });
  rejects([](RenderOptions& o) { o.height = -5; });
  rejects([](RenderOptions& o) { o.azimuth = std::nan(""); });
  rejects([](RenderOptions& o) { o.field_of_view = 0.0; });
  rejects([](RenderOptions& o) { o.field_of_view = 180.0; });
  rejects([](RenderOptions& o) { o.lighting.direction = Vec3::Zero(); });
  rejects([](RenderOptions& o) { o.isophote_stripes = 0; });
  rejects([](RenderOptions& o) { o.supersampling = 0; });
  rejects([](RenderOptions& o) { o.supersampling = 5; });
  rejects([](RenderOptions& o) { o.range = 0.0; });
  rejects([](RenderOptions& o) { o.range = INFINITY; });
  rejects([](RenderOptions& o) { o.percentile = 0.0; });
  rejects([](RenderOptions& o) { o.mode = RenderMode::ScalarField; });  // neither values nor field
  rejects([](RenderOptions& o) {
    o.mode = RenderMode::Error;
    o.field = "distance";  // the sphere has no attributes
  });
  rejects([](RenderOptions& o) {
    o.mode = RenderMode::ScalarField;
    o.values = {1.0, 2.0};  // not one per vertex
  });
  EXPECT_THROW(render_mesh(Mesh{}, RenderOptions{}), InputError);
  Mesh broken = sphere;
  broken.triangles.push_back({0, 1, 9999});
  EXPECT_THROW(render_mesh(broken, RenderOptions{}), InputError);
}

TEST(Render, LargestSideIsAccepted) {
  RenderOptions o;
  o.width = kMaxImageSide;
  o.height = 16;
  o.supersampling = 1;
  const Image image = render_mesh(test::uv_sphere(1.0, 6, 8), o);
  EXPECT_EQ(image.width(), kMaxImageSide);
  EXPECT_EQ(image.height(), 16);
}

}  // namespace
}  // namespace isopatch
