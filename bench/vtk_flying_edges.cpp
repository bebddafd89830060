// isopatch_vtk_peer: VTK's Flying Edges on an isopatch surface, a peer of the performance report
// (scripts/performance_report.sh). f is sampled on a grid with isopatch's batch evaluation (timed as
// part of Flying Edges), vtkFlyingEdges3D extracts f = 0 and the mesh is written with isopatch's
// writer; a summary (or one JSON line with --json) gives the vertex count and the wall times.
// Errors print one line on stderr and exit with isopatch's codes (2 usage, 3 input, 4 unknown
// surface, 5 parse, 6 file, 1 internal).
#include <isopatch/mesh_io.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

#include "peer_support/peer_support.hpp"
#include "tool_errors.hpp"
#include "vtk_peer/flying_edges.hpp"

namespace {

using Arguments = isopatch::bench::SurfacePeerArguments<isopatch::bench::FlyingEdgesOptions>;

int run(const Arguments& a) {
  using namespace isopatch;
  const auto [surface, r] =
      bench::mesh_and_write(a, [&a](const Surface& s) { return bench::flying_edges(s, s.box(), a.options); });
  if (a.output.json) {
    std::printf(
        "{\"system\":\"flying_edges\",\"surface\":\"%s\",\"vertices\":%zu,\"triangles\":%zu,\"ms\":%.6f,"
        "\"sample_ms\":%.6f,\"contour_ms\":%.6f,\"convert_ms\":%.6f,\"grid\":%d,\"samples\":[%d,%d,%d],"
        "\"value_evaluations\":%zu,\"non_finite_values\":%zu,\"degenerate_dropped\":%zu,\"threads\":%d,"
        "\"smp_backend\":\"%s\",\"output\":\"%s\"}\n",
        surface->name().c_str(), r.mesh.vertex_count(), r.mesh.triangle_count(), 1e3 * r.seconds,
        1e3 * r.sample_seconds, 1e3 * r.contour_seconds, 1e3 * r.convert_seconds, a.options.grid,
        r.samples[0], r.samples[1], r.samples[2], r.value_evaluations, r.non_finite_values,
        r.degenerate_dropped, a.options.threads, r.smp_backend.c_str(), a.output.path.c_str());
  } else {
    std::printf("surface    %s (VTK Flying Edges)\n", surface->name().c_str());
    std::printf("vertices   %zu\ntriangles  %zu\n", r.mesh.vertex_count(), r.mesh.triangle_count());
    std::printf("grid       %d x %d x %d points (%zu evaluations of f)\n", r.samples[0], r.samples[1],
                r.samples[2], r.value_evaluations);
    if (r.non_finite_values > 0)
      std::printf("non-finite %zu values of f taken as positive\n", r.non_finite_values);
    std::printf("time       %.3f ms (sampling %.3f, contour %.3f, conversion %.3f; %d threads, %s)\n",
                1e3 * r.seconds, 1e3 * r.sample_seconds, 1e3 * r.contour_seconds, 1e3 * r.convert_seconds,
                a.options.threads, r.smp_backend.c_str());
    std::printf("wrote      %s\n", a.output.path.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"VTK Flying Edges on an isopatch surface (a peer of the performance report)"};
  Arguments a;
  a.add_to(app);
  app.add_option("--grid", a.options.grid, "Cells along the longest side of the box")->capture_default_str();
  app.add_option("--threads", a.options.threads, "Threads of the sampling and of VTK's SMP back end")
      ->capture_default_str();
  return isopatch::bench::run_tool("isopatch_vtk_peer", app, argc, argv, [&] { return run(a); });
}
