// `isopatch mesh`: SURFACE (catalogue name, formula or @file) -> Settings -> mesh_surface -> file.
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_support.hpp"
#include "commands.hpp"

namespace isopatch::cli {
namespace {

struct MeshOptions {
  std::string surface;
  std::string output;
  std::string method = "projection";
  std::string box;
  std::vector<std::string> params;
  std::string edge_root = "bracketed";
  int grid = 64;
  double grid_offset = 1e-3;
  std::size_t max_vertices = 0;
  bool quiet = false;
};

void print_summary(const std::string& surface_name, const Settings& settings, const MeshStats& stats,
                   const std::string& output) {
  std::printf("surface    %s (%s)\n", surface_name.c_str(), method_name(settings.method).c_str());
  std::printf("vertices   %s\n", group_digits(stats.vertices).c_str());
  std::printf("triangles  %s\n", group_digits(stats.triangles).c_str());
  std::printf("f evals    %s\n", group_digits(stats.value_evaluations).c_str());
  if (stats.gradient_evaluations > 0)
    std::printf("grad evals %s\n", group_digits(stats.gradient_evaluations).c_str());
  for (const auto& [name, value] : stats.extra) std::printf("%-10s %g\n", name.c_str(), value);
  std::printf("time       %.3f s\n", stats.seconds);
  std::printf("wrote      %s\n", output.c_str());
}

int run_mesh(const MeshOptions& o) {
  Settings settings;
  settings.method = parse_method(o.method);
  if (!o.box.empty()) settings.box = parse_box(o.box);
  settings.grid = o.grid;
  settings.grid_offset = o.grid_offset;
  if (o.edge_root == "bracketed") settings.edge_root = EdgeRoot::Bracketed;
  else if (o.edge_root == "linear") settings.edge_root = EdgeRoot::Linear;
  else throw InputError("unknown --edge-root '" + o.edge_root + "' (want bracketed or linear)");
  settings.max_vertices = o.max_vertices;

  check_output_path(o.output);
  const SurfacePtr surface = resolve_surface(o.surface, settings.box, parse_params(o.params));
  MeshStats stats;
  const Mesh mesh = mesh_surface(*surface, settings, &stats);
  write_mesh(mesh, o.output);
  if (!o.quiet) print_summary(surface->name(), settings, stats, o.output);
  return 0;
}

}  // namespace

Runner add_mesh_command(CLI::App& app) {
  auto o = std::make_shared<MeshOptions>();
  CLI::App* cmd = app.add_subcommand("mesh", "Mesh an implicit surface f(x,y,z) = 0 and write the mesh");
  cmd->add_option("surface", o->surface, "Catalogue name (see 'isopatch surfaces'), a formula, or @file")->required();
  cmd->add_option("-o,--output", o->output, "Output mesh: .ply, .obj, .off or .stl")->required();
  cmd->add_option("--method", o->method, "projection | mc (marching cubes)")->capture_default_str();
  cmd->add_option("--box", o->box, "Region x0,y0,z0,x1,y1,z1 (a formula needs one)");
  cmd->add_option("--param", o->params, "Override a definition of the formula: name=value (repeatable)");
  cmd->add_option("--grid", o->grid, "Marching cubes: cells along the longest box axis")->capture_default_str();
  cmd->add_option("--edge-root", o->edge_root, "Marching cubes: bracketed | linear edge crossings")
      ->capture_default_str();
  cmd->add_option("--grid-offset", o->grid_offset, "Marching cubes: grid shift as a fraction of a cell")
      ->capture_default_str();
  cmd->add_option("--max-vertices", o->max_vertices, "Stop with an error beyond this many vertices (0: none)");
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing on success");
  return [o] { return run_mesh(*o); };
}

}  // namespace isopatch::cli
