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

#include "composite_model/composite.hpp"
#include "composite_model/composite_mesh_parts.hpp"

namespace isopatch {

/// Meshes `composite` by projection. Reads from `settings`: edge_length / max_error / size_field (curve
/// segments: the curve's length over the target size, 1..64), resolution (> 0: that many segments on
/// every curve), coordinates, max_ray_angle, march_steps, refinement_levels, remesh_iterations and
/// quality (the per-patch clean-up; default kDefaultRemeshIterations), the budgets (max_vertices,
/// cancel; evaluation and time budgets are the caller's, see mesh_composite()), base (Automatic and
/// Coons: the Coons patch over the known curves; Barycentric: the corners' combination). The caller
/// (mesh_composite()) handles region, frame and cells. With vertex_roles the mesh gets the attribute
/// "role" (core/vertex_role.hpp): Corner, Side (a curve sample), Interior (Remeshed after the
/// clean-up), FanCentre.
/// Runs in the caller's task arena; the same mesh for any number of threads. Fills `stats` (projection,
/// cleanup) when given. \throw InputError from check_composite() (composite_model/composite_checks.hpp) or
/// for invalid settings; EvaluationError when a function is
///        not finite where needed; LimitError for the budgets.
CompositeMesh mesh_composite_projection(const Composite& composite, const Settings& settings,
                                        MeshStats* stats = nullptr);

}  // namespace isopatch
