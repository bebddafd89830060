// isopatch_cgal_remesh: CGAL's isotropic_remeshing on a mesh file, the second stage of the
// "Flying Edges + isotropic remeshing" peer of the performance report (scripts/performance_report.sh).
// Reads the mesh with isopatch's reader, remeshes it (the time covers the remeshing alone, not the
// files) and writes the result with isopatch's writer; a summary or one JSON line with --json.
// Errors print one line on stderr and exit with isopatch's codes (2 usage, 3 input, 6 file, 1 internal).
#include <isopatch/mesh_io.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

#include "cgal_peer/isotropic_remesh.hpp"
#include "peer_support/peer_support.hpp"
#include "tool_errors.hpp"

namespace {

struct Arguments {
  std::string input;
  isopatch::bench::OutputArguments output;
  isopatch::bench::RemeshOptions options;
};

int run(const Arguments& a) {
  using namespace isopatch;
  a.output.check();
  const Mesh input = read_mesh(a.input);
  const bench::RemeshResult r = bench::isotropic_remesh(input, a.options);
  write_mesh(r.mesh, a.output.path);
  if (a.output.json) {
    std::printf(
        "{\"system\":\"isotropic_remeshing\",\"input\":\"%s\",\"input_vertices\":%zu,\"vertices\":%zu,"
        "\"triangles\":%zu,\"ms\":%.6f,\"target_edge\":%.17g,\"iterations\":%d,\"output\":\"%s\"}\n",
        a.input.c_str(), input.vertex_count(), r.mesh.vertex_count(), r.mesh.triangle_count(),
        1e3 * r.seconds, r.target_edge, a.options.iterations, a.output.path.c_str());
  } else {
    std::printf("input      %s (%zu vertices)\n", a.input.c_str(), input.vertex_count());
    std::printf("vertices   %zu\ntriangles  %zu\n", r.mesh.vertex_count(), r.mesh.triangle_count());
    std::printf("target     edge %.6g, %d iterations\n", r.target_edge, a.options.iterations);
    std::printf("time       %.3f ms\nwrote      %s\n", 1e3 * r.seconds, a.output.path.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"CGAL isotropic_remeshing of a mesh file (a peer of the performance report)"};
  Arguments a;
  app.add_option("mesh", a.input, "Input mesh: .ply, .obj, .off or .stl")->required();
  a.output.add_to(app);
  auto* edge = app.add_option("--edge-length", a.options.target_edge, "Target edge length");
  app.add_option(
         "--vertices", a.options.target_vertices,
         "Aim at this many vertices (target edge from the input's area); default: the input's mean edge")
      ->excludes(edge);
  app.add_option("--iterations", a.options.iterations, "Rounds of remeshing")->capture_default_str();
  return isopatch::bench::run_tool("isopatch_cgal_remesh", app, argc, argv, [&] { return run(a); });
}
