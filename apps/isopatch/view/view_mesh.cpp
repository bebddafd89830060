// mesh_request, view_mesh_file and error_json (view_mesh.hpp).
#include "view/view_mesh.hpp"

#include <isopatch/curvature.hpp>
#include <isopatch/expression.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/resolve_surface.hpp>

#include <chrono>
#include <cmath>

#include "glb_colours.hpp"

namespace isopatch::view {
namespace {

using nlohmann::json;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

json number_or_null(double x) {
  return std::isfinite(x) ? json(x) : json(nullptr);
}

// Counts, quality and the field names, then the GLB.
void finish(ViewMesh& view, const Surface* surface) {
  const Mesh& mesh = view.mesh;
  json& s = view.summary;
  s["vertices"] = mesh.vertex_count();
  s["triangles"] = mesh.triangle_count();
  s["valence_6"] = number_or_null(analyze_valence(mesh).share_6);
  s["min_angle"] = number_or_null(analyze_shape(mesh).min_angle.min);
  json fields = json::array();
  for (const VertexAttribute& a : mesh.attributes) fields.push_back(a.name);
  s["fields"] = fields;
  const Box box = bounding_box(mesh);
  s["bounds"] = {box.lo.x(), box.lo.y(), box.lo.z(), box.hi.x(), box.hi.y(), box.hi.z()};
  view.glb = encode_mesh(mesh, MeshFormat::Glb, cli::glb_colours(mesh, surface, "mean_curvature"));
}

}  // namespace

ViewMesh mesh_request(const MeshRequest& request, const std::atomic<bool>* cancel) {
  const auto start = std::chrono::steady_clock::now();
  const SurfacePtr surface = resolve_surface(request.surface, request.settings.box);
  Settings settings = request.settings;
  settings.cancel = cancel;
  MeshStats stats;
  ViewMesh view;
  view.mesh = mesh_surface(*surface, settings, &stats);
  const double mesh_seconds = seconds_since(start);
  attach_fields(view.mesh, *surface);
  json& s = view.summary;
  s["name"] = surface->name();
  s["surface"] = request.surface;
  const Box& box = settings.box ? *settings.box : surface->box();
  s["box"] = {box.lo.x(), box.lo.y(), box.lo.z(), box.hi.x(), box.hi.y(), box.hi.z()};
  s["quality"] = quality_name(settings.quality);
  s["seconds"] = mesh_seconds;
  if (const auto& c = stats.creases)
    s["creases"] = {
        {"faces", c->faces}, {"creases", c->creases}, {"corners", c->corners}, {"pieces", c->pieces}};
  finish(view, surface.get());
  s["total_seconds"] = seconds_since(start);
  return view;
}

ViewMesh view_mesh_file(Mesh mesh, const std::string& name, const Surface* surface) {
  ViewMesh view;
  view.mesh = std::move(mesh);
  if (surface != nullptr) {
    attach_fields(view.mesh, *surface);
  } else if (view.mesh.find_attribute("mean_curvature") == nullptr ||
             view.mesh.find_attribute("gaussian_curvature") == nullptr) {
    const DiscreteCurvature c = discrete_curvature(view.mesh);
    view.mesh.set_attribute("mean_curvature", std::vector<float>(c.mean.begin(), c.mean.end()));
    view.mesh.set_attribute("gaussian_curvature", std::vector<float>(c.gaussian.begin(), c.gaussian.end()));
  }
  view.summary["name"] = name;
  view.summary["file"] = true;
  finish(view, surface);
  return view;
}

json error_json(const Error& error) {
  static constexpr const char* kKinds[] = {
      "internal", "invalid_argument", "unknown_surface", "parse", "io", "evaluation", "no_surface",
      "limit",    "singular_surface", "crease"};
  json j;
  j["error"] = error.what();
  j["kind"] = kKinds[static_cast<int>(error.kind())];
  if (!error.setting().empty()) j["setting"] = error.setting();
  if (const auto* parse = dynamic_cast<const ParseError*>(&error)) {
    j["line"] = parse->line();
    j["column"] = parse->column();
    j["excerpt"] = parse->excerpt();
  }
  return j;
}

}  // namespace isopatch::view
