// `isopatch compare SURFACE`: Marching Cubes, MC + fairing and projection at matched vertex counts.
#include <isopatch/compare.hpp>
#include <isopatch/composite_mesh.hpp>
#include <isopatch/curvature.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/render.hpp>
#include <isopatch/resolve_surface.hpp>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_support.hpp"
#include "commands.hpp"

namespace isopatch::cli {
namespace {

struct CompareOptions {
  std::string surface;
  std::string box;
  std::vector<std::string> params;
  std::vector<double> edge_lengths;
  int resolution = Settings{}.resolution;
  int fair = 10;
  bool json = false;
  std::string images;
};

void print_table(const std::string& name, const std::vector<ComparisonRow>& rows) {
  std::printf("%s: marching cubes, MC + Laplace fairing and projection at matched vertex counts\n\n",
              name.c_str());
  std::printf("%-11s %8s %9s %11s %7s %9s %8s %10s %8s\n", "method", "vertices", "time ms", "evaluations",
              "val6 %", "min angle", "<20 %", "normal err", "H nRMS");
  int level = -1;
  for (const ComparisonRow& r : rows) {
    if (r.level != level && level >= 0) std::printf("\n");
    level = r.level;
    std::printf("%-11s %8zu %9.1f %11llu %7.1f %9.2f %8.1f %10.3f %8.4f\n", r.method.c_str(), r.vertices,
                1e3 * r.seconds, static_cast<unsigned long long>(r.evaluations), 100.0 * r.valence6,
                r.min_angle, 100.0 * r.share_below_20, r.normal_error, r.h_nrms);
  }
}

void print_json(const std::string& name, const std::vector<ComparisonRow>& rows) {
  nlohmann::json out;
  out["surface"] = name;
  for (const ComparisonRow& r : rows)
    out["rows"].push_back({{"method", r.method},
                           {"level", r.level},
                           {"vertices", r.vertices},
                           {"seconds", r.seconds},
                           {"evaluations", r.evaluations},
                           {"valence6", r.valence6},
                           {"min_angle", r.min_angle},
                           {"share_below_20", r.share_below_20},
                           {"normal_error", r.normal_error},
                           {"h_nrms", r.h_nrms}});
  std::cout << out.dump(2) << "\n";
}

/// One picture per level: wireframe over mean-curvature error, the three methods side by side.
void write_images(const std::string& folder, const Surface& surface, std::vector<ComparisonRow>& rows) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (!fs::is_directory(folder)) throw IoError("cannot create folder '" + folder + "'");
  const int tile = 400;
  for (std::size_t first = 0; first + 2 < rows.size(); first += 3) {
    Image sheet(3 * tile, tile);
    for (std::size_t k = 0; k < 3; ++k) {
      ComparisonRow& row = rows[first + k];
      attach_fields(row.mesh, surface);
      RenderOptions options;
      options.width = options.height = tile;
      options.mode = RenderMode::ScalarField;
      options.field = "mean_curvature";
      options.caption = row.method;
      const Image picture = render_mesh(row.mesh, options);
      for (int y = 0; y < tile; ++y)
        for (int x = 0; x < tile; ++x) sheet.set(static_cast<int>(k) * tile + x, y, picture.at(x, y));
    }
    const std::string path =
        (fs::path(folder) / ("compare_level" + std::to_string(rows[first].level) + ".png")).string();
    write_png(sheet, path);
    std::fprintf(stderr, "wrote %s\n", path.c_str());
  }
}

int run_compare(const CompareOptions& o) {
  ComparisonSettings settings;
  if (!o.box.empty()) settings.base.box = parse_box(o.box);
  settings.base.resolution = o.resolution;
  settings.edge_lengths = o.edge_lengths;
  settings.fair_iterations = o.fair;
  if (is_composite_path(o.surface) && !o.params.empty())
    throw InputError("--param is for formulas, not composite surfaces (.ipatch)");
  std::optional<CompositeModel> composite;  // a .ipatch file: projection meshes it with its known curves
  if (is_composite_path(o.surface)) composite.emplace(read_composite(o.surface));
  const SurfacePtr surface = composite
                                 ? composite->surface()
                                 : resolve_surface(o.surface, settings.base.box, parse_params(o.params));
  std::vector<ComparisonRow> rows =
      composite ? compare_methods(*composite, settings) : compare_methods(*surface, settings);
  if (o.json)
    print_json(surface->name(), rows);
  else
    print_table(surface->name(), rows);
  if (!o.images.empty()) write_images(o.images, *surface, rows);
  return 0;
}

}  // namespace

Runner add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd =
      app.add_subcommand("compare", "Compare marching cubes, MC + fairing and projection on a surface");
  cmd->add_option("surface", o->surface, "Catalogue name, formula, @file or a composite surface (.ipatch)")
      ->required();
  cmd->add_option("--box", o->box, "Region x0,y0,z0,x1,y1,z1 (a formula needs one)");
  cmd->add_option("--param", o->params, "Override a definition of the formula: name=value");
  cmd->add_option("--edge-length", o->edge_lengths, "Projection edge lengths, one per density level");
  cmd->add_option("--resolution", o->resolution, "Projection: segments per patch side")
      ->capture_default_str();
  cmd->add_option("--fair", o->fair, "Rounds of Laplace fairing for the mc+fair rows")->capture_default_str();
  cmd->add_flag("--json", o->json, "Print JSON instead of a table");
  cmd->add_option("--images", o->images, "Write one picture per level (mean curvature) into this folder");
  return [o] { return run_compare(*o); };
}

}  // namespace isopatch::cli
