// The stages of the surface-bound clean-up (remesh_on_surface): their names, as RemeshStats::times and
// the benchmarks spell them, and the order a run takes them in.
#pragma once

#include <isopatch/remesh.hpp>

#include <string_view>
#include <vector>

namespace isopatch::cleanup_stages {

inline constexpr char kSizes[] = "cleanup_sizes";                   ///< grading of the size field
inline constexpr char kSplit[] = "cleanup_split";                   ///< splits of long edges
inline constexpr char kCollapse[] = "cleanup_collapse";             ///< collapses of short edges
inline constexpr char kFlip[] = "cleanup_flip";                     ///< greedy valence flips
inline constexpr char kRelax[] = "cleanup_relax";                   ///< tangential relaxation
inline constexpr char kRepair[] = "cleanup_repair";                 ///< small-angle repair
inline constexpr char kValenceSearch[] = "cleanup_valence_search";  ///< flip chains that may borrow
inline constexpr char kCurvature[] = "cleanup_curvature";           ///< Laplacian exactness sweeps
inline constexpr char kErrorBound[] = "cleanup_error_bound";        ///< splits beyond RemeshSizes::max_error

}  // namespace isopatch::cleanup_stages

namespace isopatch {

/// The order of the clean-up's stages for some settings: `setup` once, then `round` settings.iterations
/// times (empty for a local run, RemeshSettings::local_only), then `finish` once. A stage inside a loop
/// that stops early (the repair rounds: until a repair changes nothing, at most three) or that depends on
/// the mesh (a local run's valence search: only below its valence-six share) is listed once, as when it
/// runs. A run with settings.iterations == 0 takes no stage.
struct CleanupSchedule {
  std::vector<std::string_view> setup;
  std::vector<std::string_view> round;
  std::vector<std::string_view> finish;
};

/// The schedule of remesh_on_surface for `settings` (stage names of cleanup_stages); settings valid
/// (check_remesh_settings).
CleanupSchedule cleanup_schedule(const RemeshSettings& settings);

}  // namespace isopatch
