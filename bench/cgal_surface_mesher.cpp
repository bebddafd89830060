// isopatch_cgal_peer: CGAL's Surface_mesher on an isopatch surface, the peer of the quality report
// (scripts/quality_report.sh). The surface is given exactly as to `isopatch mesh` (catalogue name,
// formula or @file, --box, --param); the mesh is written with isopatch's writer; a summary (or one
// JSON line with --json) gives the vertex count and the wall time of the meshing alone.
// Errors print one line on stderr and exit with isopatch's codes (2 usage, 3 input, 4 unknown
// surface, 5 parse, 6 file, 8 no surface in the box, 1 internal).
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

#include "cgal_peer/peer_mesher.hpp"
#include "peer_support/peer_support.hpp"
#include "tool_errors.hpp"

namespace {

using Arguments = isopatch::bench::SurfacePeerArguments<isopatch::bench::PeerOptions>;

int run(const Arguments& a) {
  using namespace isopatch;
  const auto [surface, r] = bench::mesh_and_write(
      a, [&a](const Surface& s) { return bench::cgal_surface_mesh(s, s.box(), a.options); });
  const double ms = 1e3 * r.seconds;
  if (a.output.json) {
    std::printf(
        "{\"system\":\"cgal\",\"surface\":\"%s\",\"vertices\":%zu,\"triangles\":%zu,\"ms\":%.6f,"
        "\"radius_bound\":%.17g,\"distance_bound\":%.17g,\"angle_bound\":%.17g,\"box_facets_removed\":%zu,"
        "\"non_finite_values\":%zu,\"output\":\"%s\"}\n",
        surface->name().c_str(), r.mesh.vertex_count(), r.mesh.triangle_count(), ms, a.options.radius_bound,
        a.options.distance_bound > 0 ? a.options.distance_bound : a.options.radius_bound / 10,
        a.options.angle_bound, r.box_facets_removed, r.non_finite_values, a.output.path.c_str());
  } else {
    std::printf("surface    %s (CGAL Surface_mesher)\n", surface->name().c_str());
    std::printf("vertices   %zu\ntriangles  %zu\n", r.mesh.vertex_count(), r.mesh.triangle_count());
    std::printf("seed       %.6g %.6g %.6g (sphere radius %.6g)\n", r.seed.x(), r.seed.y(), r.seed.z(),
                r.sphere_radius);
    if (r.box_facets_removed > 0) std::printf("box facets %zu removed\n", r.box_facets_removed);
    if (r.non_finite_values > 0)
      std::printf("non-finite %zu values of f counted positive\n", r.non_finite_values);
    std::printf("time       %.3f ms\nwrote      %s\n", ms, a.output.path.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"CGAL Surface_mesher on an isopatch surface (the peer of the quality report)"};
  Arguments a;
  a.add_to(app);
  app.add_option("--radius", a.options.radius_bound, "Radius bound of the surface Delaunay balls (size)")
      ->capture_default_str();
  app.add_option("--distance", a.options.distance_bound, "Distance bound (default: radius / 10)");
  app.add_option("--angle", a.options.angle_bound, "Angle bound in degrees")->capture_default_str();
  app.add_option("--error-bound", a.options.error_bound,
                 "Oracle bisection precision, relative to the sphere radius")
      ->capture_default_str();
  app.add_option("--initial-points", a.options.initial_points, "Initial points on the surface")
      ->capture_default_str();
  app.add_flag("--keep-box-faces", a.options.keep_box_faces,
               "Keep the facets closing an open surface on the box");
  return isopatch::bench::run_tool("isopatch_cgal_peer", app, argc, argv, [&] { return run(a); });
}
