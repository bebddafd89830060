#pragma once
// Multiresolution meshing (RefineSettings, docs/algorithms.md 8): the projection mesher and the
// clean-up make a coarse base at k times the target edge length; src/refine cuts every base triangle
// into k^2 triangles on f = 0. The level follows the surface's curvature, and drops (down to 1, the
// projection mesher and the clean-up at the target size) where a refinement fails its guard.

#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include "api/size_estimate.hpp"
#include "refine/refine_mesh.hpp"

#include <functional>

namespace isopatch {

/// Meshes `surface` with `settings` at one level: the projection mesher and the clean-up.
using LevelMesher = std::function<Mesh(const Settings&, MeshStats*)>;

/// How the bases of a kind of surface are measured and refined, for surfaces that are not one function
/// (a composite: every patch on its own function). An empty member means the plain surface's own:
/// refine::largest_curvature of the base's vertices on `surface`, refine::refine_mesh on `surface`.
/// Both are given the base the LevelMesher returned last.
struct BaseRefinement {
  std::function<double(const Mesh& base)> largest_curvature;
  std::function<refine::RefineResult(const Mesh& base, const refine::RefineParams& params)> refine;
  /// The automatic level keeps a refinement only when its smallest angle is at least the clean-up's
  /// floor (25 degrees) or within half a degree of the base's own, besides the usual 20 degrees.
  bool keep_base_angles = false;
};

/// How far below the base's own smallest angle (degrees) a kept refinement may go where the base's
/// angles are the measure (BaseRefinement::keep_base_angles; tiles by planes).
inline constexpr double kBaseAngleSlack = 0.5;

/// Whether the level is chosen from the surface's curvature: the automatic level (settings.refine 0)
/// without an error bound or a size field (which keep one level, docs/algorithms.md 8.4).
bool level_from_curvature(const Settings& settings);

/// The settings of a base at `level` times the target edge length `edge` (refine 1; an error bound k^2
/// times, a size field k times).
Settings base_settings(const Settings& settings, double edge, int level);

/// The level the first base is made at: settings.refine when given; else 1 with an error bound or a
/// size field; else the automatic level from `estimate` (when found), at most the preset's ceiling.
int first_level(const Settings& settings, double edge, const SizeEstimate* estimate);

/// The automatic level checked on a base of `base_vertices` vertices whose largest curvature is
/// `largest_curvature`: at most `level`; `level` itself when the level is not from the curvature.
int resolved_level(const Settings& settings, double edge, double largest_curvature, std::size_t base_vertices,
                   int level);

/// The refinement's parameters for `settings` at `level` in `box`: the quality preset's sweeps and
/// angle target, the box and region that cut the mesh, the vertex budget, cancel and progress.
refine::RefineParams refine_params(const Settings& settings, const Box& box, int level);

/// Whether a refinement that passed its guard with this smallest angle (degrees) is kept: always at an
/// explicit level, at the automatic one when it is at least 20 degrees (else the level is halved).
bool refinement_kept(const Settings& settings, double smallest_angle);

/// refinement_kept() for a base made of patches whose refinement keeps the base's angles
/// (BaseRefinement::keep_base_angles): at the automatic level the smallest angle must also be at least
/// the clean-up's floor (25 degrees) or within half a degree of the base's own, `base_smallest_angle`.
bool refinement_kept(const Settings& settings, double smallest_angle, double base_smallest_angle);

/// The multiresolution mesh of `surface` (settings.refine != 1, projection). `mesh_level` meshes the
/// bases (and the output itself when the level ends at 1); stats, when given, are those of the final
/// base with the evaluations and times of every attempt added and MeshStats::refine filled.
/// `estimate`, when given (the automatic level), sets the first level tried: the largest whose base
/// edge turns the normal by at most the preset's max_turn at the estimate's largest curvature and
/// leaves the preset's fewest base vertices; without it the first base is made at the preset's
/// ceiling. Either way the level is then checked on the base's own curvature. `bases` replaces how a
/// base is measured and refined (see BaseRefinement).
/// \throw as mesh_surface(): SettingError, LimitError (budgets, cancel, max_vertices), EvaluationError.
Mesh mesh_multiresolution(const Surface& surface, const Settings& settings, MeshStats* stats,
                          const LevelMesher& mesh_level, const SizeEstimate* estimate = nullptr,
                          const BaseRefinement& bases = {});

}  // namespace isopatch
