// The stages of the surface-bound clean-up (remesh_on_surface): their names, as RemeshStats::times and
// the benchmarks spell them. The order a run takes them in is its plan (cleanup_plan.hpp).
#pragma once

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
