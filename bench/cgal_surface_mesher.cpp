// isopatch_cgal_peer: CGAL's Surface_mesher on an isopatch surface, the peer of the quality report
// (scripts/quality_report.sh). The surface is given exactly as to `isopatch mesh` (catalogue name,
// formula or @file, --box, --param); the mesh is written with isopatch's writer; a summary (or one
// JSON line with --json) gives the vertex count and the wall time of the meshing alone.
// Errors print one line on stderr and exit with isopatch's codes (2 usage, 3 input, 4 unknown
// surface, 5 parse, 6 file, 8 no surface in the box, 1 internal).
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/resolve_surface.hpp>

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cgal_peer/peer_mesher.hpp"
#include "tool_errors.hpp"

namespace {

// "name=value" items -> map, as `isopatch mesh --param`. \throw InputError for a malformed item.
std::map<std::string, double> parse_params(const std::vector<std::string>& items) {
  std::map<std::string, double> params;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    double value = 0.0;
    const char* end = item.data() + item.size();
    const bool ok = eq != std::string::npos && eq > 0 && eq + 1 < item.size();
    const auto parsed = ok ? std::from_chars(item.data() + eq + 1, end, value) : std::from_chars_result{};
    if (!ok || parsed.ec != std::errc() || parsed.ptr != end || !std::isfinite(value))
      throw isopatch::InputError("bad --param '" + item + "' (want name=value with a finite number)");
    if (!params.emplace(item.substr(0, eq), value).second)
      throw isopatch::InputError("--param " + item.substr(0, eq) + " is given twice");
  }
  return params;
}

struct Arguments {
  std::string surface;
  std::string output;
  std::string box;
  std::vector<std::string> params;
  isopatch::bench::PeerOptions peer;
  bool json = false;
};

int run(const Arguments& a) {
  using namespace isopatch;
  isopatch::format_from_path(a.output);  // unknown extension: IoError before any work
  const std::optional<Box> box = a.box.empty() ? std::nullopt : std::optional<Box>(parse_box(a.box));
  const SurfacePtr surface = resolve_surface(a.surface, box, parse_params(a.params));
  const bench::PeerResult r = bench::cgal_surface_mesh(*surface, surface->box(), a.peer);
  write_mesh(r.mesh, a.output);
  const double ms = 1e3 * r.seconds;
  if (a.json) {
    std::printf(
        "{\"system\":\"cgal\",\"surface\":\"%s\",\"vertices\":%zu,\"triangles\":%zu,\"ms\":%.6f,"
        "\"radius_bound\":%.17g,\"distance_bound\":%.17g,\"angle_bound\":%.17g,\"box_facets_removed\":%zu,"
        "\"non_finite_values\":%zu,\"output\":\"%s\"}\n",
        surface->name().c_str(), r.mesh.vertex_count(), r.mesh.triangle_count(), ms, a.peer.radius_bound,
        a.peer.distance_bound > 0 ? a.peer.distance_bound : a.peer.radius_bound / 10, a.peer.angle_bound,
        r.box_facets_removed, r.non_finite_values, a.output.c_str());
  } else {
    std::printf("surface    %s (CGAL Surface_mesher)\n", surface->name().c_str());
    std::printf("vertices   %zu\ntriangles  %zu\n", r.mesh.vertex_count(), r.mesh.triangle_count());
    std::printf("seed       %.6g %.6g %.6g (sphere radius %.6g)\n", r.seed.x(), r.seed.y(), r.seed.z(),
                r.sphere_radius);
    if (r.box_facets_removed > 0) std::printf("box facets %zu removed\n", r.box_facets_removed);
    if (r.non_finite_values > 0)
      std::printf("non-finite %zu values of f counted positive\n", r.non_finite_values);
    std::printf("time       %.3f ms\nwrote      %s\n", ms, a.output.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"CGAL Surface_mesher on an isopatch surface (the peer of the quality report)"};
  Arguments a;
  app.add_option("surface", a.surface, "Catalogue name, formula or @file")->required();
  app.add_option("-o,--output", a.output, "Output mesh: .ply, .obj, .off or .stl")->required();
  app.add_option("--box", a.box, "Region x0,y0,z0,x1,y1,z1 (a formula needs one)");
  app.add_option("--param", a.params, "Override a definition of the formula: name=value (repeatable)");
  app.add_option("--radius", a.peer.radius_bound, "Radius bound of the surface Delaunay balls (size)")
      ->capture_default_str();
  app.add_option("--distance", a.peer.distance_bound, "Distance bound (default: radius / 10)");
  app.add_option("--angle", a.peer.angle_bound, "Angle bound in degrees")->capture_default_str();
  app.add_option("--error-bound", a.peer.error_bound,
                 "Oracle bisection precision, relative to the sphere radius")
      ->capture_default_str();
  app.add_option("--initial-points", a.peer.initial_points, "Initial points on the surface")
      ->capture_default_str();
  app.add_flag("--keep-box-faces", a.peer.keep_box_faces,
               "Keep the facets closing an open surface on the box");
  app.add_flag("--json", a.json, "Print one JSON line instead of a summary");
  return isopatch::bench::run_tool("isopatch_cgal_peer", app, argc, argv, [&] { return run(a); });
}
