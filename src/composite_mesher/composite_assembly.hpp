#pragma once
/// \file composite_assembly.hpp
/// The last steps of meshing a composite: each projected patch cleaned up on its own function with
/// its boundary held (patch_relaxation.hpp), then the pieces assembled into one mesh by their shared
/// curve ids, with what each element belongs to and, when asked, each vertex's role.

#include <isopatch/mesh_stats.hpp>
#include <isopatch/remesh.hpp>
#include <isopatch/settings.hpp>

#include <vector>

#include "composite_mesher/composite_rounds.hpp"
#include "composite_model/composite_mesh_parts.hpp"

namespace isopatch {

/// Cleans up every patch that is not a fan with `iterations` rounds of the preset's passes
/// (remesh_presets.hpp) at `sizes`, in parallel; first refuses (settings.check_vertices) a clean-up
/// that would split past the vertex budget with uniform sizes. Returns the clean-up's counts per patch.
/// \throw LimitError for the vertex budget or cancellation; EvaluationError.
std::vector<RemeshStats> clean_up_patches(const Composite& c, ProjectedPatches& patches,
                                          const Settings& settings, const TargetSizes& sizes, int iterations);

/// The mesh: the curves' samples first, then each patch's new vertices in patch order; counts
/// patches, fans, gradient rays and unprojected fan centres in `ps`; with settings.vertex_roles the
/// attribute "role" (core/vertex_role.hpp; Remeshed for patch interiors when `cleaned_up`).
/// \throw LimitError beyond settings.max_vertices.
CompositeMesh assemble_composite(const Composite& c, const ProjectedPatches& patches,
                                 const std::vector<int>& segments, const Settings& settings, bool cleaned_up,
                                 ProjectionStats& ps);

}  // namespace isopatch
