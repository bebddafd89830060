// `isopatch mesh`: SURFACE (catalogue name, formula or @file) -> Settings -> mesh_surface -> file.
#include <isopatch/composite_mesh.hpp>
#include <isopatch/convex_region.hpp>
#include <isopatch/curvature.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/remesh.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/self_intersection.hpp>
#include <isopatch/vdb_surface.hpp>
#include <isopatch/volume_io.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "cli_support.hpp"
#include "commands.hpp"
#include "glb_colours.hpp"
#include "mesh_warnings.hpp"
#include "progress_line.hpp"
#include "run_clock.hpp"
#include "singular_report.hpp"
#include "stats_output.hpp"
#include "tiles_runner.hpp"
#include "volume_input.hpp"

#include <tbb/task_arena.h>

namespace isopatch::cli {
namespace {

struct MeshOptions {
  std::string surface;
  std::string output;
  std::string method = "projection";
  std::string box;
  std::string region;
  std::string frame;
  std::vector<std::string> params;
  std::string edge_root = "bracketed";
  std::optional<std::string> grid;  ///< marching cubes' cells, or a .vdb input's grid name
  std::optional<int> mc_grid;
  double grid_offset = 1e-3;
  int fair = 0;
  std::size_t max_vertices = default_vertex_budget();
  bool quiet = false;
  bool progress = false;
  bool fields = false;
  bool vertex_roles = false;
  std::string colour = "mean_curvature";
  std::string stats_json;
  Settings defaults;
  std::optional<double> edge_length;
  int resolution = defaults.resolution;
  int min_depth = defaults.min_depth;
  int max_depth = defaults.max_depth;
  int refinement_levels = defaults.refinement_levels;
  double max_cell_curvature = defaults.max_cell_curvature;
  std::string coordinates = "wachspress";
  std::string base = "auto";
  std::string creases = "auto";
  double max_ray_angle = defaults.max_ray_angle;
  std::optional<int> remesh;
  int refine = defaults.refine;
  int valence_search = Settings{}.valence_search;
  int curvature_sweeps = Settings{}.curvature_sweeps;
  std::uint64_t max_evaluations = 0;
  double time_limit = 0.0;
  std::optional<double> max_error;
  bool uniform = false;
  std::string quality = "default";
  int threads = 0;
  VolumeOptions volume;
  TilesOptions tiles;
};

/// A blocked run (--tiles): only the settings the blocks keep; the others are refused, not dropped.
[[noreturn]] void run_mesh_in_tiles(const MeshOptions& o) {
  const MeshOptions d;
  const auto refuse = [](bool given, const std::string& flag) {
    if (given) throw InputError(flag + " is not available with --tiles (docs/distributed.md)", "tiles");
  };
  refuse(o.method != d.method, "--method");
  refuse(!o.region.empty(), "--region");
  refuse(!o.frame.empty(), "--frame");
  refuse(is_vdb_path(o.surface), "A .vdb grid");
  refuse(!o.volume.spacing.empty() || !o.volume.origin.empty(), "--spacing and --origin");
  refuse(o.max_error.has_value(), "--max-error");
  refuse(o.fields || o.vertex_roles, "--fields and --vertex-roles");
  refuse(!o.stats_json.empty(), "--stats-json (the manifest in --out-dir has the figures)");
  TilesJob job;
  job.surface = o.surface;
  job.output = o.output == "-" ? "" : o.output;
  job.box = o.box;
  job.params = o.params;
  job.level = o.volume.level;
  job.edge_length = o.edge_length;
  job.quality = o.quality;
  job.refine = o.refine;
  job.creases = o.creases;
  run_tiles(o.tiles, job);
}

int run_mesh(const MeshOptions& o) {
  RunClock clock;  // every second of the run in the statistics, from the process's start
  if (o.tiles.tiles != 0) run_mesh_in_tiles(o);
  // The blocked run's own flags mean nothing to one process: refused, not dropped.
  const TilesOptions d;
  for (const auto& [given, flag] :
       {std::pair{!o.tiles.out_dir.empty(), "--out-dir"},
        std::pair{o.tiles.scheduler != d.scheduler, "--scheduler"},
        std::pair{o.tiles.workers != d.workers, "--workers"},
        std::pair{!o.tiles.memory_limit.empty(), "--memory-limit"},
        std::pair{o.tiles.prefilter_window != d.prefilter_window, "--prefilter-window"},
        std::pair{o.tiles.split != d.split, "--split"}})
    if (given)
      throw InputError(std::string(flag) + " needs --tiles (a blocked run, docs/distributed.md)", "tiles");
  Settings settings;
  settings.method = parse_method(o.method);
  if (!o.box.empty()) settings.box = parse_box(o.box);
  if (!o.region.empty()) settings.region = region_argument(o.region);
  if (!o.frame.empty()) settings.frame = parse_frame(o.frame);
  settings.grid = marching_cubes_cells(o.grid, o.mc_grid, is_vdb_path(o.surface));
  settings.grid_offset = o.grid_offset;
  settings.fair_iterations = o.fair;
  if (o.edge_root == "bracketed")
    settings.edge_root = EdgeRoot::Bracketed;
  else if (o.edge_root == "linear")
    settings.edge_root = EdgeRoot::Linear;
  else
    throw InputError("unknown --edge-root '" + o.edge_root + "' (want bracketed or linear)");
  settings.max_vertices = o.max_vertices;
  settings.edge_length = o.edge_length;
  settings.resolution = o.resolution;
  settings.min_depth = o.min_depth;
  settings.max_depth = o.max_depth;
  settings.refinement_levels = o.refinement_levels;
  settings.max_cell_curvature = o.max_cell_curvature;
  settings.max_ray_angle = o.max_ray_angle;
  settings.remesh_iterations = o.remesh;
  settings.refine = o.refine;
  settings.uniform = o.uniform;
  settings.valence_search = o.valence_search;
  settings.curvature_sweeps = o.curvature_sweeps;
  settings.max_evaluations = o.max_evaluations;
  settings.time_limit = o.time_limit;
  settings.max_error = o.max_error;
  settings.quality = parse_quality(o.quality);
  settings.vertex_roles = o.vertex_roles;
  settings.threads = o.threads;
  if (o.coordinates == "wachspress")
    settings.coordinates = Settings::Coordinates::Wachspress;
  else if (o.coordinates == "mean-value")
    settings.coordinates = Settings::Coordinates::MeanValue;
  else
    throw InputError("unknown --coordinates '" + o.coordinates + "' (want wachspress or mean-value)");
  settings.creases = parse_creases(o.creases);
  if (o.base == "auto")
    settings.base = Settings::Base::Automatic;
  else if (o.base == "barycentric")
    settings.base = Settings::Base::Barycentric;
  else if (o.base == "coons")
    settings.base = Settings::Base::Coons;
  else
    throw InputError("unknown --base '" + o.base + "' (want auto, barycentric or coons)");

  check_output_path(o.output);
  check_colour_field(o.colour);
  if (!o.stats_json.empty()) check_writable_location(o.stats_json);
  const bool vdb = is_vdb_path(o.surface);
  const bool sampled = vdb || is_volume_path(o.surface);
  if (o.volume.given() && !sampled)
    throw InputError("--level, --spacing and --origin are for volumes (.npy, .nrrd, .vdb), not '" +
                     o.surface + "'");
  if (sampled && !o.params.empty()) throw InputError("--param is for formulas, not volumes");
  if (is_composite_path(o.surface) && !o.params.empty())
    throw InputError("--param is for formulas, not composite surfaces (.ipatch)");
  std::optional<CompositeModel> composite;  // a .ipatch file: its patches are meshed with their curves
  if (is_composite_path(o.surface)) composite.emplace(read_composite(o.surface));
  if (composite && settings.method != Method::MarchingCubes) {
    for (const std::string& w : composite->shape_warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  }
  const SurfacePtr surface =
      composite ? composite->surface()
      : vdb     ? vdb_input(o.surface, o.volume, o.grid.value_or(""))
      : is_volume_path(o.surface)
          ? volume_input(o.surface, o.volume)
          : resolve_surface_in_region(o.surface, settings.box, settings.region, parse_params(o.params));
  clock.add("input", clock.lap());
  // The singular points of f = 0 in the box, before meshing: the mesh is refined around them
  // (SizeSettings::refine_around), and they are listed in a warning and the statistics
  // (singular_report.hpp). The search and the checks behind the warnings run on the meshing's threads.
  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  const SingularRun singular =
      arena.execute([&] { return search_singular_points(*surface, settings, sampled); });
  if (!composite && settings.method == Method::Projection && !settings.uniform)
    settings.refine_around = singular.found.singular_samples();
  clock.add("singular_points", clock.lap());
  MeshStats stats;
  std::optional<ProgressLine> line;  // ended (newline) before anything else is printed, also on errors
  if (progress_wanted(o.progress, o.quiet)) {
    line.emplace(stderr, method_name(settings.method),
                 settings.method == Method::MarchingCubes ? "slabs" : "partition rounds");
    settings.progress = [&line](const Progress& p) { line->update(p); };
  }
  Mesh mesh =
      composite ? mesh_composite(*composite, settings, &stats) : mesh_surface(*surface, settings, &stats);
  line.reset();
  // What the call took beyond the mesher's own timer (its checks of the settings, the task arena).
  clock.add("meshing_setup", std::max(0.0, clock.lap() - stats.seconds));
  if (o.fields) attach_fields(mesh, *surface);
  clock.add("fields", clock.lap());
  const bool glb = format_from_path(o.output) == MeshFormat::Glb;
  write_mesh(mesh, o.output, glb ? glb_colours(mesh, surface.get(), o.colour) : std::vector<Vec3>{});
  clock.add("write", clock.lap());
  const SelfIntersectionReport crossings = arena.execute([&] { return find_self_intersections(mesh); });
  clock.add("self_intersections", clock.lap());
  stats.warnings.self_intersecting_pairs = crossings.pairs;
  stats.warnings.self_intersection_near = crossings.example_point;
  clock.account(stats);
  if (!o.stats_json.empty())
    write_stats_json(o.stats_json, surface->name(), settings, stats, o.output, &singular);
  if (!o.quiet) print_summary(surface->name(), settings, stats, o.output);
  print_singular_warning(singular, stderr);
  print_mesh_warnings(stats, mesh, crossings, stderr);
  return 0;
}

}  // namespace

Runner add_mesh_command(CLI::App& app) {
  auto o = std::make_shared<MeshOptions>();
  CLI::App* cmd = app.add_subcommand("mesh", "Mesh an implicit surface f(x,y,z) = 0 and write the mesh");
  cmd->add_option("surface", o->surface,
                  "Catalogue name (see 'isopatch surfaces'), a formula, @file, a sampled volume (.npy, "
                  ".nrrd), an OpenVDB grid (.vdb) or a "
                  "composite surface (.ipatch: control polyhedron or setback blends)")
      ->required();
  cmd->add_option("-o,--output", o->output,
                  "Output mesh: .ply, .obj, .off, .stl, .glb (glTF 2.0 binary) or .3mf (3MF for printing, "
                  "millimetres); optional with --tiles, which writes blocks and a manifest");
  cmd->add_option("--method", o->method, "projection | mc (marching cubes)")->capture_default_str();
  cmd->add_option("--box", o->box,
                  "Region x0,y0,z0,x1,y1,z1 (a formula needs one, unless a bounded --region stands for it)");
  cmd->add_option(
      "--region", o->region,
      "Projection: mesh inside the convex polytope of planes 'a,b,c,d;...' (a x + b y + c z + d <= 0), "
      "or @FILE with one plane a line; inside --box when given, else instead of it when bounded, else "
      "inside the surface's own box (a formula needs --box for an unbounded region)");
  cmd->add_option("--frame", o->frame, "The partition in a frame rotated by AZ,EL,ROLL degrees");
  cmd->add_option("--param", o->params, "Override a definition of the formula: name=value (repeatable)");
  cmd->add_option("--level", o->volume.level, "Volume: the level of the samples to mesh (default 0)");
  cmd->add_option("--spacing", o->volume.spacing,
                  "Volume: sample spacing sx,sy,sz (default: the NRRD header's, or 1 for .npy)");
  cmd->add_option("--origin", o->volume.origin,
                  "Volume: position of sample (0,0,0) as ox,oy,oz (default: the NRRD header's, or 0)");
  cmd->add_option("--edge-length", o->edge_length,
                  "Projection: target edge length (default: longest box side / 64)");
  cmd->add_option("--resolution", o->resolution,
                  "Projection: segments per patch side (1..64; 0: from the edge length)")
      ->capture_default_str();
  cmd->add_option("--min-depth", o->min_depth, "Projection: smallest octree depth of surface cells")
      ->capture_default_str();
  cmd->add_option("--max-depth", o->max_depth, "Projection: largest octree depth (refinement limit)")
      ->capture_default_str();
  cmd->add_option("--refinement-levels", o->refinement_levels,
                  "Projection: levels of local refinement allowed where cells fail")
      ->capture_default_str();
  cmd->add_option("--max-cell-curvature", o->max_cell_curvature,
                  "Projection: start one depth finer while most patch corners lie in cells longer than this "
                  "many curvature radii (cells of at least 3 edge lengths; 0: off)")
      ->capture_default_str();
  cmd->add_option("--coordinates", o->coordinates, "Projection: wachspress | mean-value")
      ->capture_default_str();
  cmd->add_option(
         "--base", o->base,
         "Projection: auto | barycentric | coons (exact face curves, C0 Coons base); auto: barycentric in "
         "cells, coons on a composite's patches")
      ->capture_default_str();
  cmd->add_option(
         "--creases", o->creases,
         "Formulas: auto (one built with min, max or abs whose faces meet at creases is meshed along "
         "its exact creases and corners; where they cannot be followed, smooth with a warning) | off "
         "(meshed as a smooth surface) | exact (as auto, but a shape whose creases cannot be meshed is "
         "refused, exit 11)")
      ->capture_default_str();
  cmd->add_option("--max-ray-angle", o->max_ray_angle,
                  "Projection: acceptance angle between ray and gradient")
      ->capture_default_str();
  cmd->add_option("--grid", o->grid,
                  "Marching cubes: cells along the longest box axis (default 64); a .vdb input: the name of "
                  "the grid to mesh (default: the file's only level set)");
  cmd->add_option("--mc-grid", o->mc_grid,
                  "Marching cubes: cells along the longest box axis, also for a .vdb input (same as --grid)");
  cmd->add_option("--edge-root", o->edge_root, "Marching cubes: bracketed | linear edge crossings")
      ->capture_default_str();
  cmd->add_option("--grid-offset", o->grid_offset, "Marching cubes: grid shift as a fraction of a cell")
      ->capture_default_str();
  cmd->add_option("--fair", o->fair, "Marching cubes: rounds of Laplace fairing with re-projection")
      ->capture_default_str();
  cmd->add_option("--remesh", o->remesh,
                  "Rounds of surface-bound clean-up: split, collapse, flip, relax, re-project "
                  "(default: 6 for projection, 0 for mc; 0: the paper's method alone)");
  cmd->add_option("--refine", o->refine,
                  "Projection: multiresolution level K, a base at K edge lengths cut into K^2 triangles per "
                  "base triangle and put on f = 0 (0: automatic from the curvature; 1: off, the clean-up of "
                  "the whole mesh; 2.." +
                      std::to_string(kMaxRefineLevel) + ")")
      ->capture_default_str();
  cmd->add_option(
         "--valence-search", o->valence_search,
         "Clean-up: flips tried per chain when pulling apart stuck 5-7 vertex pairs at the end (0.." +
             std::to_string(kMaxValenceSearch) + "; 0: skip, faster, slightly fewer vertices of valence 6)")
      ->capture_default_str();
  cmd->add_option("--curvature-sweeps", o->curvature_sweeps,
                  "Clean-up: sweeps of tangential vertex moves that make the cotangent Laplacian exact "
                  "for quadratics at each vertex (0.." +
                      std::to_string(kMaxCurvatureSweeps) + "; lower curvature error; 0: skip, faster)")
      ->capture_default_str();
  cmd->add_option("--max-error", o->max_error,
                  "Curvature-adapted sizes: triangle centroids stay within this distance of f = 0 "
                  "(edges at most --edge-length)");
  cmd->add_flag("--uniform", o->uniform,
                "Projection: one edge length everywhere (default: smaller, graded sizes where the box or a "
                "region plane cuts f = 0 in a feature narrower than an edge, or where f = 0 turns within an "
                "edge, as at a thin rim; reported in a warning)");
  cmd->add_option("--quality", o->quality,
                  "preview (the paper's method with a local repair: fastest, valence 6 >= 90%, angles >= "
                  "20 degrees) | default | fine (lowest curvature error)")
      ->capture_default_str();
  cmd->add_option("--threads", o->threads,
                  "Worker threads (0: every core); the mesh is the same bytes for any count")
      ->capture_default_str();
  cmd->add_option("--max-evaluations", o->max_evaluations,
                  "Stop with an error after this many evaluations of f (0: none)");
  cmd->add_option("--time-limit", o->time_limit, "Stop with an error after this many seconds (0: none)");
  cmd->add_option("--max-vertices", o->max_vertices,
                  "Refuse a mesh estimated beyond this many vertices before any work, and stop beyond it "
                  "(0: none; default: what this machine's memory holds)")
      ->capture_default_str();
  cmd->add_flag("--vertex-roles", o->vertex_roles,
                "Projection: store what made each vertex as the attribute 'role' (0 patch corner, 1 seam, 2 "
                "patch interior, 3 patch centre, 4 fan centre, 5 made by the clean-up; PLY, GLB)");
  cmd->add_flag(
      "--fields", o->fields,
      "Store discrete and exact mean and Gaussian curvature and the distance to f = 0 per vertex (PLY, "
      "glTF)");
  cmd->add_option("--colour", o->colour,
                  std::string(".glb: the field shown as vertex colours (COLOR_0): ") + kGlbColourFields)
      ->capture_default_str();
  cmd->add_option("--tiles", o->tiles.tiles,
                  "Mesh as N blocks refined on Dask workers (docs/distributed.md); needs --out-dir");
  cmd->add_option("--out-dir", o->tiles.out_dir,
                  "--tiles: the directory of the block files and the manifest");
  cmd->add_option("--scheduler", o->tiles.scheduler,
                  "--tiles: 'local' (a cluster on 127.0.0.1) or tcp://HOST:PORT of a Dask scheduler")
      ->capture_default_str();
  cmd->add_option("--workers", o->tiles.workers, "--tiles: worker processes of the local cluster")
      ->capture_default_str();
  cmd->add_option("--memory-limit", o->tiles.memory_limit, "--tiles: memory per local worker, e.g. 2GB");
  cmd->add_option("--prefilter-window", o->tiles.prefilter_window,
                  "--tiles with a volume: samples per side of the prefilter's windows (default 192)");
  cmd->add_option(
         "--split", o->tiles.split,
         "--tiles: 'blocks' of one base made by the driver, or 'planes': tiles of the box by planes, "
         "each making its own base (for bases beyond one machine)")
      ->check(CLI::IsMember({"blocks", "planes"}))
      ->capture_default_str();
  cmd->add_option("--stats-json", o->stats_json,
                  "Also write every statistic of the run to this file as JSON (by stage, by name)");
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing on success (and no progress line)");
  cmd->add_flag(
      "--progress", o->progress,
      "Show a progress line on stderr even when it is not a terminal (default: only on a terminal)");
  // -o is required unless the run is blocked (usage error, exit 2, like any missing argument).
  cmd->parse_complete_callback([o] {
    if (o->tiles.tiles == 0 && o->output.empty()) throw CLI::RequiredError("--output");
  });
  return [o] { return run_mesh(*o); };
}

}  // namespace isopatch::cli
