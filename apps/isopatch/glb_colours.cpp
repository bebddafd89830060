#include "glb_colours.hpp"

#include <isopatch/curvature.hpp>
#include <isopatch/error.hpp>
#include <isopatch/render.hpp>

#include <array>
#include <string_view>

namespace isopatch::cli {
namespace {

bool known_field(const std::string& field) {
  static constexpr std::array<std::string_view, 5> kFields{
      "mean_curvature", "mean_curvature_exact", "gaussian_curvature", "gaussian_curvature_exact", "distance"};
  for (const std::string_view name : kFields)
    if (field == name) return true;
  return false;
}

std::vector<double> computed_field(const Mesh& mesh, const Surface* surface, const std::string& field) {
  if (surface != nullptr) {
    Mesh copy;
    copy.positions = mesh.positions;
    copy.triangles = mesh.triangles;
    attach_fields(copy, *surface);
    const std::vector<float>& values = *copy.find_attribute(field);
    return {values.begin(), values.end()};
  }
  if (field == "mean_curvature") return discrete_curvature(mesh).mean;
  if (field == "gaussian_curvature") return discrete_curvature(mesh).gaussian;
  throw InputError("the colour field '" + field + "' needs the surface (the mesh does not carry it)");
}

}  // namespace

void check_colour_field(const std::string& field) {
  if (field != "none" && !known_field(field))
    throw InputError("unknown colour field '" + field + "' (want " + kGlbColourFields + ")", "colour");
}

std::vector<Vec3> glb_colours(const Mesh& mesh, const Surface* surface, const std::string& field) {
  if (field == "none") return {};
  RenderOptions options;
  options.mode = field == "distance" ? RenderMode::Error : RenderMode::ScalarField;
  if (mesh.find_attribute(field) != nullptr) {
    options.field = field;
  } else {
    check_colour_field(field);
    options.values = computed_field(mesh, surface, field);
  }
  return field_vertex_colours(mesh, options);
}

}  // namespace isopatch::cli
