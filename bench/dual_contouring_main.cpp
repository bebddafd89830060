// isopatch_dual_contouring: plain Dual Contouring (Ju, Losasso, Schaefer & Warren, "Dual contouring of
// Hermite data", SIGGRAPH 2002; bench/dual_contouring/) of an isopatch surface, a peer for meshes of
// CSG shapes with creases. The surface is given as to the other peers (catalogue name, formula or
// @file, --box, --param); the grid is --cells N cubic cells along the box's longest side, or the N whose
// mesh comes closest to --vertices V. Writes the mesh with isopatch's writer and prints one line of
// key=value (or one JSON line with --json). Errors print one line on stderr and exit with isopatch's
// codes (2 usage, 3 input, 4 unknown surface, 5 parse, 6 file, 1 internal).
#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdio>

#include "dual_contouring/dual_contouring.hpp"
#include "dual_contouring/vertex_target.hpp"
#include "peer_support/peer_support.hpp"
#include "tool_errors.hpp"

namespace {

struct Resolution {
  int cells = 0;
  std::size_t vertices = 0;
};

using Arguments = isopatch::bench::SurfacePeerArguments<Resolution>;

int run(const Arguments& a) {
  using namespace isopatch;
  const auto [surface, r] = bench::mesh_and_write(a, [&a](const Surface& s) {
    bench::DualContouringOptions options;
    if (a.options.vertices > 0)
      return bench::dual_contouring_for_vertices(s, s.box(), a.options.vertices, options);
    options.cells = a.options.cells;
    return bench::dual_contouring(s, s.box(), options);
  });
  if (a.output.json)
    std::printf(
        "{\"system\":\"dual_contouring\",\"cells\":%d,\"grid\":[%d,%d,%d],\"vertices\":%zu,\"triangles\":%zu,"
        "\"seconds\":%.6f,\"runs\":%d,\"search_seconds\":%.6f,\"clamped\":%zu,\"boundary_edges\":%zu,"
        "\"non_finite\":%zu}\n",
        r.cells, r.grid[0], r.grid[1], r.grid[2], r.mesh.vertex_count(), r.mesh.triangle_count(), r.seconds,
        r.search_runs, r.search_seconds, r.clamped_vertices, r.boundary_edges, r.non_finite_values);
  else
    std::printf(
        "cells=%d grid=%dx%dx%d vertices=%zu triangles=%zu seconds=%.6f runs=%d search_seconds=%.6f "
        "clamped=%zu "
        "boundary_edges=%zu non_finite=%zu\n",
        r.cells, r.grid[0], r.grid[1], r.grid[2], r.mesh.vertex_count(), r.mesh.triangle_count(), r.seconds,
        r.search_runs, r.search_seconds, r.clamped_vertices, r.boundary_edges, r.non_finite_values);
  return 0;
}

// Everything that can throw is inside run_tool, except setting up the command line (out of memory).
int run_main(int argc, char** argv) {
  CLI::App app{"Plain Dual Contouring (Ju et al. 2002) of an isopatch surface (a peer for CSG shapes)"};
  Arguments a;
  a.add_to(app);
  CLI::App* resolution = app.add_option_group("resolution", "The grid: one of --cells and --vertices");
  resolution->add_option("--cells", a.options.cells, "Cubic cells along the longest side of the box")
      ->check(CLI::Range(2, isopatch::bench::kMaxSearchCells));
  resolution
      ->add_option("--vertices", a.options.vertices,
                   "Choose the cells so the mesh has about this many vertices")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000000}));
  resolution->require_option(1);
  return isopatch::bench::run_tool("isopatch_dual_contouring", app, argc, argv, [&] { return run(a); });
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run_main(argc, argv);
  } catch (...) {
    std::fprintf(stderr, "isopatch_dual_contouring: internal error while setting up the command line\n");
    return 1;
  }
}
