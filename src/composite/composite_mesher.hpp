#pragma once
/// \file composite_mesher.hpp
/// A composite surface (ipatch/composite.hpp) meshed by projection, as Sipos & Salvi 2021, sec. 4, mesh
/// composites of I-patches: the corners and boundary curves come from the construction (no face curve
/// is traced), every curve is sampled once with its own segment count and both patches that use it
/// take those samples, so the mesh is watertight by vertex ids without welding; each patch is the
/// multi-sided C0 Coons patch over its sides, its interior projected onto the patch's own function
/// inside its region (patch_projection.hpp). A rejected patch doubles the segments of its curves and
/// the patches are meshed again (at most OctreeSettings::refinement_levels rounds); one still rejected
/// then is closed by a fan (counted). Finally each patch is cleaned up on its own function with its
/// boundary fixed (patch_relaxation.hpp), unless remesh_iterations is 0 (the paper's method alone).

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>

#include <cstdint>
#include <vector>

#include "ipatch/composite.hpp"

namespace isopatch {

/// A composite's mesh with what each element belongs to.
struct CompositeMesh {
  Mesh mesh;
  /// Per vertex: the patch whose interior it lies in, or -1 for a vertex on a curve (a corner or a
  /// curve sample, shared by the patches that meet there). The first vertices are the curves'.
  std::vector<std::int32_t> vertex_patch;
  /// Per triangle: its patch.
  std::vector<std::uint32_t> triangle_patch;
  /// Per curve: the segments it was sampled with.
  std::vector<int> curve_segments;
  /// Per curve: its vertices from its start to its end (curve_segments + 1 of them; none for a curve
  /// no patch uses).
  std::vector<std::vector<std::uint32_t>> curve_vertices;
};

/// Checks the composite's topology: 3..12 sides per patch with as many finite non-zero corner
/// directions, curve ids in range, side k ending exactly where side k + 1 starts, every curve used at
/// most twice and, when twice, in opposite directions.
/// \throw InputError naming the patch or curve otherwise.
void check_composite(const Composite& composite);

/// Meshes `composite` by projection. Reads from `settings`: edge_length / max_error / size_field (curve
/// segments: the curve's length over the target size, 1..64), resolution (> 0: that many segments on
/// every curve), coordinates, max_ray_angle, march_steps, refinement_levels, remesh_iterations and
/// quality (the per-patch clean-up; default kDefaultRemeshIterations), the budgets (max_vertices,
/// cancel; evaluation and time budgets are the caller's, see mesh_composite()). `settings.base` is not
/// read: the base is always the Coons patch over the known curves. With vertex_roles the mesh gets the
/// attribute "role": 0 corner, 1 curve sample, 2 patch interior (5 after the clean-up), 4 fan centre.
/// Runs in the caller's task arena; the same mesh for any number of threads. Fills `stats` (projection,
/// cleanup) when given. \throw InputError from check_composite() or for invalid settings; EvaluationError
/// when a function is
///        not finite where needed; LimitError for the budgets.
CompositeMesh mesh_composite_projection(const Composite& composite, const Settings& settings,
                                        MeshStats* stats = nullptr);

}  // namespace isopatch
