// isopatch_ideal_lattice: the H nRMS an ideal lattice of equilateral triangles would give on a
// surface, at the vertex count and area of a given mesh (bench/ideal_lattice/ideal_rings.hpp). The
// quality report sets it beside a measured H nRMS. The surface is given as to `isopatch analyze`
// (catalogue name, formula or @file, --box). Prints a summary, or one JSON line with --json.
// Errors print one line on stderr and exit with isopatch's codes (2 usage, 3 input, 4 unknown
// surface, 5 parse, 6 file, 1 internal).
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/resolve_surface.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <map>
#include <optional>
#include <string>

#include "ideal_lattice/ideal_rings.hpp"
#include "tool_errors.hpp"

namespace {

struct Arguments {
  std::string mesh;
  std::string surface;
  std::string box;
  std::string sizes = "uniform";
  isopatch::bench::IdealRingOptions options;
  bool json = false;
};

int run(Arguments a) {
  using namespace isopatch;
  a.options.sizes = a.sizes == "graded" ? bench::RingSizes::Graded : bench::RingSizes::Uniform;
  const std::optional<Box> box = a.box.empty() ? std::nullopt : std::optional<Box>(parse_box(a.box));
  const SurfacePtr surface = resolve_surface(a.surface, box);
  const Mesh mesh = read_mesh(a.mesh);
  const bench::IdealRingResult r = bench::ideal_ring_error(mesh, *surface, a.options);
  if (a.json) {
    std::printf(
        "{\"surface\":\"%s\",\"vertices\":%zu,\"sizes\":\"%s\",\"edge\":%.17g,\"nrms_mean\":%.17g,"
        "\"nrms_best\":%.17g,\"samples\":%zu,\"skipped\":%zu}\n",
        surface->name().c_str(), mesh.vertex_count(), a.sizes.c_str(), r.edge, r.nrms_mean, r.nrms_best,
        r.samples, r.skipped);
  } else {
    std::printf("surface    %s, %zu vertices\n", surface->name().c_str(), mesh.vertex_count());
    std::printf("rings      %s, %s %.6g\n", a.sizes.c_str(),
                a.sizes == "graded" ? "edge * sqrt(kappa_max)" : "edge", r.edge);
    std::printf("H nRMS     %.4g over %d orientations, %.4g at each point's best\n", r.nrms_mean,
                a.options.orientations, r.nrms_best);
    std::printf("samples    %zu (%zu skipped)\n", r.samples, r.skipped);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"H nRMS of ideal equilateral rings at a mesh's vertex count (the quality report's yardstick)"};
  Arguments a;
  app.add_option("mesh", a.mesh, "Mesh whose vertices (on the surface) are the sample points")->required();
  app.add_option("--surface", a.surface, "Catalogue name, formula or @file")->required();
  app.add_option("--box", a.box, "Region x0,y0,z0,x1,y1,z1 (a formula needs one)");
  app.add_option("--sizes", a.sizes, "uniform: one edge length; graded: c / sqrt(kappa_max)")
      ->check(CLI::IsMember({"uniform", "graded"}))
      ->capture_default_str();
  app.add_option("--orientations", a.options.orientations, "Lattice angles tried per point")
      ->check(CLI::Range(1, 60))
      ->capture_default_str();
  app.add_option("--max-samples", a.options.max_samples, "At most this many interior vertices")
      ->check(CLI::Range(std::size_t{1}, std::size_t{10000000}))
      ->capture_default_str();
  app.add_flag("--json", a.json, "Print one JSON line instead of a summary");
  return isopatch::bench::run_tool("isopatch_ideal_lattice", app, argc, argv, [&] { return run(a); });
}
