#pragma once
/// \file remesh_presets.hpp
/// The clean-up's settings that a quality preset (CleanupSettings::quality) chooses, shared by every
/// caller of the remesher (the whole-surface clean-up of src/api and the per-patch clean-up of
/// src/composite_mesher), so that one preset means the same passes everywhere (docs/algorithms.md 5.3).

#include <isopatch/remesh.hpp>
#include <isopatch/settings.hpp>

namespace isopatch {

/// What a clean-up does once its preset is applied.
struct CleanupEffort {
  int iterations = 0;               ///< rounds over the whole mesh (a local run: > 0, none taken)
  int valence_search = 0;           ///< flips per chain of the borrowing sweep; 0: none
  int curvature_sweeps = 0;         ///< Laplacian-exactness sweeps; 0: none
  bool local_only = false;          ///< the preview's local repair instead of the rounds
  int final_relaxation_rounds = 0;  ///< relaxation-only rounds once connectivity is final
};

/// The effort of clean-up settings `c` (valid): remesh_iterations (empty: kDefaultRemeshIterations),
/// the valence search and curvature sweeps as set and 8 final relaxation rounds, adjusted by the preset:
/// preview is the local repair (local_only), default leaves them as set, fine doubles the curvature
/// sweeps and the valence search (within kMaxCurvatureSweeps and kMaxValenceSearch) and takes 12 final
/// relaxation rounds.
CleanupEffort cleanup_effort(const CleanupSettings& c);

/// RemeshSettings for a meshing run's settings `s` with `iterations` rounds: its clean-up settings
/// (remesh_iterations set to `iterations`), cancel flag and progress. Sizes, box and region are the
/// caller's.
RemeshSettings preset_remesh_settings(const Settings& s, int iterations);

}  // namespace isopatch
