#pragma once
// Multiresolution meshing (RefineSettings, docs/algorithms.md 8): the projection mesher and the
// clean-up make a coarse base at k times the target edge length; src/refine cuts every base triangle
// into k^2 triangles on f = 0. The level follows the surface's curvature, and drops (down to 1, the
// projection mesher and the clean-up at the target size) where a refinement fails its guard.

#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include "api/size_estimate.hpp"

#include <functional>

namespace isopatch {

/// Meshes `surface` with `settings` at one level: the projection mesher and the clean-up.
using LevelMesher = std::function<Mesh(const Settings&, MeshStats*)>;

/// Whether the level is chosen from the surface's curvature: the automatic level (settings.refine 0)
/// without an error bound or a size field (which keep one level, docs/algorithms.md 8.4).
bool level_from_curvature(const Settings& settings);

/// The multiresolution mesh of `surface` (settings.refine != 1, projection). `mesh_level` meshes the
/// bases (and the output itself when the level ends at 1); stats, when given, are those of the final
/// base with the evaluations and times of every attempt added and MeshStats::refine filled.
/// `estimate`, when given (the automatic level), sets the first level tried: the largest whose base
/// edge turns the normal by at most the preset's max_turn at the estimate's largest curvature and
/// leaves the preset's fewest base vertices; without it the first base is made at the preset's
/// ceiling. Either way the level is then checked on the base's own curvature.
/// \throw as mesh_surface(): SettingError, LimitError (budgets, cancel, max_vertices), EvaluationError.
Mesh mesh_multiresolution(const Surface& surface, const Settings& settings, MeshStats* stats,
                          const LevelMesher& mesh_level, const SizeEstimate* estimate = nullptr);

}  // namespace isopatch
