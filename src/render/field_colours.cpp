// field_vertex_colours (render.hpp) and the field values and range it shares with render_mesh.
#include <isopatch/error.hpp>
#include <isopatch/render.hpp>

#include <algorithm>
#include <cmath>

#include "render/colour_map.hpp"
#include "render/render_options.hpp"

namespace isopatch {
namespace render {

std::vector<double> field_values(const Mesh& mesh, const RenderOptions& o) {
  if (!o.values.empty()) {
    if (o.values.size() != mesh.vertex_count())
      throw InputError("render: " + std::to_string(o.values.size()) + " values for " +
                       std::to_string(mesh.vertex_count()) + " vertices");
    return o.values;
  }
  if (o.field.empty())
    throw InputError("render: this mode needs per-vertex values or the name of an attribute");
  const std::vector<float>* attribute = mesh.find_attribute(o.field);
  if (attribute == nullptr) throw InputError("render: the mesh has no vertex attribute '" + o.field + "'");
  return std::vector<double>(attribute->begin(), attribute->end());
}

double colour_range(const std::vector<double>& values, const RenderOptions& o) {
  if (o.range) return *o.range;
  double m = robust_magnitude(values, o.percentile);
  if (m == 0.0) m = robust_magnitude(values, 100.0);
  return m > 0.0 ? m : 1.0;  // all zero (or no finite value): any range shows them the same
}

}  // namespace render

namespace {

// The sRGB transfer function undone: the renderer's colours are display values.
double to_linear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace

std::vector<Colour> field_vertex_colours(const Mesh& mesh, const RenderOptions& options, RenderInfo* info) {
  render::check_options(options);
  if (!render::is_field_mode(options.mode))
    throw InputError("render: vertex colours need a field mode (ScalarField or Error)");
  const std::vector<double> values = render::field_values(mesh, options);
  const double range = render::colour_range(values, options);
  std::vector<Colour> colours;
  colours.reserve(values.size());
  RenderInfo summary;
  summary.range = range;
  for (const double v : values) {
    Colour c = options.missing_colour;
    if (std::isfinite(v))
      c = options.mode == RenderMode::Error ? render::sequential_colour(std::abs(v) / range)
                                            : render::diverging_colour(v / range);
    else
      ++summary.missing_values;
    colours.emplace_back(to_linear(c.x()), to_linear(c.y()), to_linear(c.z()));
  }
  if (info != nullptr) *info = summary;
  return colours;
}

}  // namespace isopatch
