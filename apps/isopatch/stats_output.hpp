#pragma once
// The statistics of `isopatch mesh`: a summary on stdout, and the same numbers as JSON for scripts.

#include <isopatch/isopatch.hpp>

#include <string>

#include "singular_report.hpp"

namespace isopatch::cli {

/// Prints the summary: surface and method, vertex and triangle counts, evaluations, then every stage's
/// statistics by name (visit_stats), the time and the output path.
void print_summary(const std::string& surface_name, const Settings& settings, const MeshStats& stats,
                   const std::string& output);

/// Writes every statistic (visit_stats) to `path` as one JSON object: "surface", "method", "output",
/// then one object per stage that ran ("mesh", "projection", "cleanup", "warnings", ...), numbers by
/// name, and, when `singular` is given, "singular_points" (singular_json). \throw IoError when the file
/// cannot be written.
void write_stats_json(const std::string& path, const std::string& surface_name, const Settings& settings,
                      const MeshStats& stats, const std::string& output,
                      const SingularRun* singular = nullptr);

}  // namespace isopatch::cli
