// render_mesh: checks the options, then camera -> visibility (depth buffer of triangle indices) ->
// per-sample shading -> wireframe overlay -> box-filter downsampling -> legend and caption. Shading is
// deferred (one evaluation per visible sample) so its cost does not grow with overdraw.
#include <isopatch/error.hpp>
#include <isopatch/render.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "render/camera.hpp"
#include "render/colour_map.hpp"
#include "render/font.hpp"
#include "render/legend.hpp"
#include "render/rasterizer.hpp"
#include "render/render_options.hpp"
#include "render/shading.hpp"

namespace isopatch {
namespace {

using render::Camera;
using render::ScreenPoint;

constexpr double kMaxSamples = 67108864.0;  // 2^26 samples of the supersampled canvas
constexpr double kEdgeWidth = 1.0;          // wireframe lines, in output pixels
constexpr double kEdgeDepthBias = 0.01;     // in bounding-sphere radii: edges win over their own faces

}  // namespace

namespace render {

void check_options(const RenderOptions& o) {
  auto fail = [](const std::string& message) { throw InputError("render: " + message); };
  if (o.width < 1 || o.width > kMaxImageSide || o.height < 1 || o.height > kMaxImageSide)
    fail("image size " + std::to_string(o.width) + "x" + std::to_string(o.height) + " is outside 1.." +
         std::to_string(kMaxImageSide) + " per side");
  if (!std::isfinite(o.azimuth) || !std::isfinite(o.elevation)) fail("the view angles must be finite");
  if (!(o.field_of_view > 0.0 && o.field_of_view < 170.0))
    fail("the field of view must be in (0, 170) degrees");
  if (!o.lighting.direction.allFinite() || o.lighting.direction.norm() == 0.0)
    fail("the light direction must be a finite non-zero vector");
  if (o.isophote_stripes < 1) fail("isophotes need at least one stripe");
  if (o.supersampling < 1 || o.supersampling > 4) fail("supersampling must be 1..4");
  if (o.range && !(std::isfinite(*o.range) && *o.range > 0.0)) fail("the range must be finite and positive");
  if (!(o.percentile > 0.0 && o.percentile <= 100.0)) fail("the percentile must be in (0, 100]");
  if (!(o.lighting.field_ambient >= 0.0 && o.lighting.field_ambient <= 1.0))
    fail("the field modes' ambient light must be in [0, 1]");
}

}  // namespace render

namespace {

// The largest supersampling factor not above the requested one within the sample budget.
int supersampling_for(const RenderOptions& o) {
  int ss = o.supersampling;
  while (ss > 1 && static_cast<double>(o.width) * o.height * ss * ss > kMaxSamples) --ss;
  return ss;
}

// Everything the per-sample shading needs, computed once.
struct Scene {
  const Mesh* mesh = nullptr;
  Camera camera;
  std::vector<ScreenPoint> screen;
  std::vector<Vec3> normals;  // camera coordinates
  std::vector<double> values;
  double range = 1.0;
};

Colour sample_colour(const Scene& scene, const RenderOptions& o, std::uint32_t t, double x, double y) {
  const Triangle& tri = scene.mesh->triangles[t];
  const std::array<ScreenPoint, 3> corners = {scene.screen[tri[0]], scene.screen[tri[1]],
                                              scene.screen[tri[2]]};
  const std::array<double, 3> w = render::interpolation_weights(corners, x, y, scene.camera);
  const bool front = render::signed_area(corners[0], corners[1], corners[2]) < 0.0;
  Vec3 n = w[0] * scene.normals[tri[0]] + w[1] * scene.normals[tri[1]] + w[2] * scene.normals[tri[2]];
  if (n.norm() < 1e-12) {  // vertex normals cancel: fall back to the flat normal
    const Vec3& a = scene.mesh->positions[tri[0]];
    n = scene.camera.to_camera((scene.mesh->positions[tri[1]] - a).cross(scene.mesh->positions[tri[2]] - a));
  }
  n.normalize();
  if (!front) n = -n;
  const Colour& base = front ? o.surface_colour : o.back_colour;
  switch (o.mode) {
    case RenderMode::Shaded:
    case RenderMode::Wireframe:
      return render::shaded_colour(base, n, o.lighting);
    case RenderMode::Isophotes: {
      const Colour lit = render::shaded_colour(base, n, o.lighting);
      const int stripe = render::isophote_stripe(n, o.lighting.direction.normalized(), o.isophote_stripes);
      return stripe % 2 == 0 ? lit : Colour(render::kDarkStripe * lit);
    }
    case RenderMode::ScalarField:
    case RenderMode::Error: {
      const double v =
          w[0] * scene.values[tri[0]] + w[1] * scene.values[tri[1]] + w[2] * scene.values[tri[2]];
      Colour c = o.missing_colour;
      if (std::isfinite(v))
        c = o.mode == RenderMode::Error ? render::sequential_colour(std::abs(v) / scene.range)
                                        : render::diverging_colour(v / scene.range);
      return render::field_colour(c, n, o.lighting);
    }
  }
  return base;
}

void draw_edges(const Scene& scene, const render::DepthBuffer& buffer, const RenderOptions& o, int ss,
                Image& canvas) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * scene.mesh->triangle_count());
  for (const Triangle& t : scene.mesh->triangles)
    for (int k = 0; k < 3; ++k) edges.emplace_back(std::minmax(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const Rgb colour = render::to_rgb8(o.edge_colour);
  const double bias = kEdgeDepthBias * scene.camera.radius;
  for (const auto& [a, b] : edges)
    render::draw_segment(canvas, buffer, scene.screen[a], scene.screen[b], scene.camera, kEdgeWidth * ss,
                         bias, colour);
}

// Averages ss x ss blocks of samples into one pixel each.
Image downsample(const Image& canvas, int ss) {
  if (ss == 1) return canvas;
  Image image(canvas.width() / ss, canvas.height() / ss);
  const int n = ss * ss;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      int sum[3] = {0, 0, 0};
      for (int dy = 0; dy < ss; ++dy)
        for (int dx = 0; dx < ss; ++dx) {
          const Rgb c = canvas.at(x * ss + dx, y * ss + dy);
          sum[0] += c.r;
          sum[1] += c.g;
          sum[2] += c.b;
        }
      auto average = [n](int s) { return static_cast<std::uint8_t>((s + n / 2) / n); };
      image.set(x, y, Rgb{average(sum[0]), average(sum[1]), average(sum[2])});
    }
  return image;
}

}  // namespace

Image render_mesh(const Mesh& mesh, const RenderOptions& options, RenderInfo* info) {
  render::check_options(options);
  mesh.validate();
  if (mesh.triangle_count() == 0) throw InputError("render: the mesh has no triangles");

  Scene scene;
  scene.mesh = &mesh;
  RenderInfo summary;
  const bool field_mode = render::is_field_mode(options.mode);
  if (field_mode) {
    scene.values = render::field_values(mesh, options);
    scene.range = render::colour_range(scene.values, options);
    summary.range = scene.range;
    summary.missing_values = static_cast<std::size_t>(
        std::count_if(scene.values.begin(), scene.values.end(), [](double v) { return !std::isfinite(v); }));
  }
  const render::Legend legend{options.mode == RenderMode::ScalarField, scene.range};
  const bool show_legend = field_mode && options.legend;

  // The mesh gets the picture left of the legend, unless the legend would leave it less than half.
  int mesh_width = options.width;
  if (show_legend) {
    const int strip = render::legend_width(options.width, options.height, legend);
    if (2 * strip <= options.width) mesh_width -= strip;
  }
  const int ss = supersampling_for(options);
  const render::Viewport viewport{0.0, 0.0, static_cast<double>(mesh_width * ss),
                                  static_cast<double>(options.height * ss)};
  scene.camera = render::fit_camera(mesh.positions, options, viewport);
  scene.screen.reserve(mesh.vertex_count());
  for (const Vec3& p : mesh.positions) scene.screen.push_back(scene.camera.project(p));
  scene.normals = vertex_normals(mesh);
  for (Vec3& n : scene.normals) n = scene.camera.to_camera(n);

  render::DepthBuffer buffer(options.width * ss, options.height * ss);
  render::rasterize(mesh.triangles, scene.screen, scene.camera, buffer);

  Image canvas(buffer.width, buffer.height, render::to_rgb8(options.background));
  for (int y = 0; y < buffer.height; ++y)
    for (int x = 0; x < buffer.width; ++x) {
      const std::uint32_t t = buffer.triangle[buffer.index(x, y)];
      if (t != render::kNoTriangle)
        canvas.set(x, y, render::to_rgb8(sample_colour(scene, options, t, x + 0.5, y + 0.5)));
    }
  if (options.mode == RenderMode::Wireframe) draw_edges(scene, buffer, options, ss, canvas);

  Image image = downsample(canvas, ss);
  if (show_legend) render::draw_legend(image, legend);
  if (!options.caption.empty()) {
    const int scale = render::text_scale(image.width(), image.height());
    render::draw_text(image, 8 * scale, 8 * scale, options.caption, scale, Rgb{26, 26, 30});
  }
  if (info != nullptr) *info = summary;
  return image;
}

}  // namespace isopatch
