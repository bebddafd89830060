// `isopatch render`: MESH (+ SURFACE for fields the mesh does not carry) -> RenderOptions ->
// render_mesh -> PNG.
#include <isopatch/curvature.hpp>
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/render.hpp>
#include <isopatch/resolve_surface.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "cli_support.hpp"
#include "commands.hpp"

namespace isopatch::cli {
namespace {

struct RenderCommandOptions {
  std::string mesh;
  std::string output;
  std::string show = "shaded";
  std::string surface;
  std::string box;
  std::vector<std::string> params;
  std::string view = "30,25";
  std::string size = "800x800";
  std::optional<double> range;
  std::string field;
  std::string projection = "perspective";
  int stripes = 12;
  bool no_legend = false;
  std::string caption;
  bool quiet = false;
};

// A --show value: the mode and, for the field modes, the attribute it reads by default.
struct Show {
  RenderMode mode;
  std::string field;
};

Show parse_show(const std::string& name) {
  if (name == "shaded") return {RenderMode::Shaded, ""};
  if (name == "wireframe") return {RenderMode::Wireframe, ""};
  if (name == "isophotes") return {RenderMode::Isophotes, ""};
  if (name == "mean-curvature") return {RenderMode::ScalarField, "mean_curvature"};
  if (name == "gaussian-curvature") return {RenderMode::ScalarField, "gaussian_curvature"};
  if (name == "error") return {RenderMode::Error, "distance"};
  if (name == "field") return {RenderMode::ScalarField, ""};
  throw InputError(
      "unknown --show '" + name +
      "' (want shaded, wireframe, isophotes, mean-curvature, gaussian-curvature, error or field)");
}

double parse_number(const std::string& text, const std::string& what) {
  double value = 0.0;
  const char* b = text.data();
  const char* e = b + text.size();
  if (b != e && *b == '+') ++b;
  const auto [ptr, ec] = std::from_chars(b, e, value);
  if (text.empty() || ec != std::errc() || ptr != e || !std::isfinite(value))
    throw InputError("bad " + what + ": '" + text + "' is not a finite number");
  return value;
}

// "a,b" -> azimuth, elevation in degrees.
std::pair<double, double> parse_view(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos)
    throw InputError("bad --view '" + text + "' (want azimuth,elevation in degrees)");
  return {parse_number(text.substr(0, comma), "--view azimuth"),
          parse_number(text.substr(comma + 1), "--view elevation")};
}

// "WxH" -> width, height; the range is checked by render_mesh.
std::pair<int, int> parse_size(const std::string& text) {
  const auto x = text.find_first_of("xX");
  auto parse_side = [&](const std::string& side) {
    int value = 0;
    const auto [ptr, ec] = std::from_chars(side.data(), side.data() + side.size(), value);
    if (side.empty() || ec != std::errc() || ptr != side.data() + side.size())
      throw InputError("bad --size '" + text + "' (want WIDTHxHEIGHT in pixels, e.g. 800x600)");
    return value;
  };
  if (x == std::string::npos)
    throw InputError("bad --size '" + text + "' (want WIDTHxHEIGHT in pixels, e.g. 800x600)");
  return {parse_side(text.substr(0, x)), parse_side(text.substr(x + 1))};
}

// Checks before any work that the picture can be written where asked.
void check_png_path(const std::string& path) {
  namespace fs = std::filesystem;
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".png") throw IoError("cannot write '" + path + "': the picture must be a .png file");
  check_writable_location(path);
}

RenderOptions to_render_options(const RenderCommandOptions& o, const Show& show) {
  RenderOptions r;
  r.mode = show.mode;
  std::tie(r.width, r.height) = parse_size(o.size);
  std::tie(r.azimuth, r.elevation) = parse_view(o.view);
  if (o.projection == "perspective")
    r.camera = CameraKind::Perspective;
  else if (o.projection == "orthographic")
    r.camera = CameraKind::Orthographic;
  else
    throw InputError("unknown --projection '" + o.projection + "' (want perspective or orthographic)");
  const bool field_mode = show.mode == RenderMode::ScalarField || show.mode == RenderMode::Error;
  if (!field_mode && !o.field.empty())
    throw InputError("--field needs a field view (--show field, mean-curvature, ...)");
  if (!field_mode && o.range)
    throw InputError("--range needs a field view (--show field, mean-curvature, ...)");
  if (o.show == "field" && o.field.empty()) throw InputError("--show field needs --field NAME");
  r.field = o.field.empty() ? show.field : o.field;
  r.range = o.range;
  r.isophote_stripes = o.stripes;
  r.legend = !o.no_legend;
  r.caption = o.caption;
  return r;
}

int run_render(const RenderCommandOptions& o) {
  const Show show = parse_show(o.show);
  const RenderOptions options = to_render_options(o, show);
  check_png_path(o.output);
  Mesh mesh = read_mesh(o.mesh);
  const bool field_mode = show.mode == RenderMode::ScalarField || show.mode == RenderMode::Error;
  if (field_mode && !o.surface.empty()) {
    // Fresh fields against the surface replace whatever the file carried under the same names.
    const SurfacePtr surface = resolve_surface_for_mesh(o.surface, o.box, o.params, mesh);
    attach_fields(mesh, *surface);
  } else if (field_mode && mesh.find_attribute(options.field) == nullptr) {
    throw InputError("mesh '" + o.mesh + "' has no vertex attribute '" + options.field +
                     "'; pass --surface to compute it, or write it with 'isopatch analyze --write'");
  }
  RenderInfo info;
  const Image image = render_mesh(mesh, options, &info);
  write_png(image, o.output);
  if (!o.quiet) {
    std::printf("wrote      %s (%dx%d, %s)\n", o.output.c_str(), image.width(), image.height(),
                o.show.c_str());
    if (field_mode) {
      std::printf("field      %s\n", options.field.c_str());
      if (show.mode == RenderMode::Error)
        std::printf("range      0 .. %g\n", info.range);
      else
        std::printf("range      -%g .. %g\n", info.range, info.range);
      if (info.missing_values > 0)
        std::printf("undefined  %s vertices (grey)\n", group_digits(info.missing_values).c_str());
    }
  }
  return 0;
}

}  // namespace

Runner add_render_command(CLI::App& app) {
  auto o = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd =
      app.add_subcommand("render", "Draw a mesh into a PNG picture (shaded, wireframe, curvature, ...)");
  cmd->add_option("mesh", o->mesh, "Mesh file: .ply, .obj, .off or .stl")->required();
  cmd->add_option("-o,--output", o->output, "Output picture (.png)")->required();
  cmd->add_option("--show", o->show,
                  "shaded | wireframe | isophotes | mean-curvature | gaussian-curvature | error | field")
      ->capture_default_str();
  cmd->add_option(
      "--surface", o->surface,
      "Surface to compute curvature and distance fields against, a composite (.ipatch) too (else they "
      "are read from the mesh)");
  cmd->add_option("--box", o->box,
                  "Box of a --surface formula: x0,y0,z0,x1,y1,z1 (default: the mesh's bounds)");
  cmd->add_option("--param", o->params,
                  "Override a definition of the --surface formula: name=value (repeatable)");
  cmd->add_option("--field", o->field, "Vertex attribute to colour by (e.g. mean_curvature_exact)");
  cmd->add_option("--range", o->range, "Colour map range m: [-m, m], or [0, m] for error (default: robust)");
  cmd->add_option("--view", o->view, "Camera azimuth,elevation in degrees (z is up)")->capture_default_str();
  cmd->add_option("--size", o->size, "Picture size WIDTHxHEIGHT in pixels (each 1..8192)")
      ->capture_default_str();
  cmd->add_option("--projection", o->projection, "perspective | orthographic")->capture_default_str();
  cmd->add_option("--stripes", o->stripes, "Isophotes: number of stripes")->capture_default_str();
  cmd->add_flag("--no-legend", o->no_legend, "Field views: leave out the colour bar");
  cmd->add_option("--caption", o->caption, "Text at the top left of the picture");
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing on success");
  return [o] { return run_render(*o); };
}

}  // namespace isopatch::cli
