// Statistics of `isopatch mesh` as text and JSON (stats_output.hpp).
#include "stats_output.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <isopatch/mesh_io.hpp>

#include <nlohmann/json.hpp>

#include "cli_support.hpp"

namespace isopatch::cli {

void print_summary(const std::string& surface_name, const Settings& settings, const MeshStats& stats,
                   const std::string& output) {
  std::printf("surface    %s (%s)\n", surface_name.c_str(), method_name(settings.method).c_str());
  std::printf("vertices   %s\n", group_digits(stats.vertices).c_str());
  std::printf("triangles  %s\n", group_digits(stats.triangles).c_str());
  std::printf("f evals    %s\n", group_digits(stats.value_evaluations).c_str());
  if (stats.gradient_evaluations > 0)
    std::printf("grad evals %s\n", group_digits(stats.gradient_evaluations).c_str());
  visit_stats(stats, [](std::string_view stage, std::string_view name, double value) {
    if (stage == "seconds" && name != "total")
      std::printf("stage      %-22.*s %.4f s\n", static_cast<int>(name.size()), name.data(), value);
    else if (stage != "mesh")
      std::printf("%-10.*s %g\n", static_cast<int>(name.size()), name.data(), value);
  });
  std::printf("threads    %d\n", stats.threads);
  std::printf("meshing    %.6f s\n", stats.seconds);
  // The whole run from the process's start (the stage "total" the command's clock adds), else the mesher's.
  const double total = stats.times.of("total");
  std::printf("time       %.6f s\n", total > 0.0 ? total : stats.seconds);
  std::printf("wrote      %s\n", output.c_str());
}

void write_stats_json(const std::string& path, const std::string& surface_name, const Settings& settings,
                      const MeshStats& stats, const std::string& output, const SingularRun* singular) {
  nlohmann::ordered_json j = {
      {"surface", surface_name}, {"method", method_name(settings.method)}, {"output", output}};
  visit_stats(stats, [&j](std::string_view stage, std::string_view name, double value) {
    auto& entry = j[std::string(stage)][std::string(name)];
    // Counts as integers: every count is exact in a double below 2^53.
    if (std::nearbyint(value) == value && std::abs(value) < 0x1p53)
      entry = static_cast<std::int64_t>(value);
    else
      entry = value;
  });
  if (singular) j["singular_points"] = singular_json(*singular);
  write_whole_file(path, j.dump(2) + "\n");
}

}  // namespace isopatch::cli
