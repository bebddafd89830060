#pragma once
/// \file remesh_presets.hpp
/// The clean-up's settings that a quality preset (CleanupSettings::quality) chooses, shared by every
/// caller of the remesher (the whole-surface clean-up of src/api and the per-patch clean-up of
/// src/composite_mesher), so that one preset means the same passes everywhere (docs/algorithms.md 5.3).

#include <isopatch/remesh.hpp>
#include <isopatch/settings.hpp>

namespace isopatch {

/// RemeshSettings with `iterations` rounds, the valence search, curvature sweeps and cancel flag of
/// `s`, adjusted by its preset: preview is the local repair (RemeshSettings::local_only), default leaves
/// them as set, fine doubles the curvature sweeps and the valence search (within kMaxCurvatureSweeps and
/// kMaxValenceSearch) and takes 12 final relaxation rounds. Sizes, box and region are the caller's.
RemeshSettings preset_remesh_settings(const Settings& s, int iterations);

}  // namespace isopatch
