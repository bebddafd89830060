// Library errors in the command line's words (error_report.hpp).
#include "error_report.hpp"

#include <array>
#include <string_view>
#include <utility>

namespace isopatch::cli {

int exit_code(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Internal:
      return 1;
    case ErrorKind::InvalidArgument:
      return 3;
    case ErrorKind::UnknownSurface:
      return 4;
    case ErrorKind::Parse:
      return 5;
    case ErrorKind::Io:
      return 6;
    case ErrorKind::Evaluation:
      return 7;
    case ErrorKind::NoSurface:
      return 8;
    case ErrorKind::Limit:
      return 9;
    case ErrorKind::SingularSurface:
      return 10;
    case ErrorKind::Crease:
      return 11;
  }
  return 1;
}

std::string flag_for_setting(const std::string& setting) {
  // Settings fields whose flag is not their name with dashes.
  // (Fields no flag sets, such as max_boundary_ray_angle, march_steps or size_field, are in neither.)
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kRenamed{{
      {"params", "--param"},
      {"fair_iterations", "--fair"},
      {"remesh_iterations", "--remesh"},
  }};
  static constexpr std::array<std::string_view, 31> kSameName{"box",
                                                              "region",
                                                              "frame",
                                                              "colour",
                                                              "method",
                                                              "edge_length",
                                                              "max_error",
                                                              "resolution",
                                                              "min_depth",
                                                              "max_depth",
                                                              "refinement_levels",
                                                              "max_cell_curvature",
                                                              "coordinates",
                                                              "base",
                                                              "creases",
                                                              "max_ray_angle",
                                                              "grid",
                                                              "edge_root",
                                                              "grid_offset",
                                                              "refine",
                                                              "valence_search",
                                                              "curvature_sweeps",
                                                              "max_evaluations",
                                                              "time_limit",
                                                              "threads",
                                                              "quality",
                                                              "max_vertices",
                                                              "level",
                                                              "spacing",
                                                              "origin",
                                                              "port"};
  for (const auto& [name, flag] : kRenamed)
    if (setting == name) return std::string(flag);
  for (const std::string_view name : kSameName)
    if (setting == name) {
      std::string flag = "--" + setting;
      for (char& c : flag)
        if (c == '_') c = '-';
      return flag;
    }
  return {};
}

std::string describe(const Error& e) {
  const std::string flag = flag_for_setting(e.setting());
  return flag.empty() ? std::string(e.what()) : std::string(e.what()) + " (" + flag + ")";
}

}  // namespace isopatch::cli
