#pragma once
// A shape whose crease paths failed on a feature at the edge's scale (creases closer than an edge at the
// box, a strip between creases narrower than one) meshed again along its creases at half the edge length
// (then a quarter), before it would be rounded or refused (docs/lattices.md, "Features at the edge's scale").

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <optional>
#include <string>

#include "api/apart_meshing.hpp"

namespace isopatch {

/// Whether a crease path's refusal names a feature at the edge's scale, which a smaller edge length may
/// mesh (creases closer than an edge, a strip narrower than one, a piece too short), not a shape that is
/// no 2-manifold or a face the general path cannot cut.
bool finer_edge_may_help(const std::string& failure);

/// When finer_edge_may_help(failure), the settings ask for a uniform edge length (no max_error, no size
/// field) and fewer than two retries are running on this thread: `surface` meshed through `mesh` (the
/// whole entry point) at half of `edge`, creases asked exact, so that the result is meshed along its
/// creases or not at all (where that fails on such a feature again, the retry inside it tries a quarter of
/// `edge`). On success the statistics are the retry's, with MeshWarnings::creases_finer_edge set to the
/// edge length used and crease_failure to `failure`. nullopt (stats untouched) when not tried, when
/// the retry is refused (CreaseError) or when its estimate exceeds settings.max_vertices (LimitError
/// "max_vertices"). Follows no paper: the global form of a local size from the feature's width.
/// \throw the other errors of `mesh` (a time limit, an evaluation error).
std::optional<Mesh> mesh_at_half_edge(const Surface& surface, const Settings& settings, MeshStats* stats,
                                      const std::string& failure, double edge, const WallMesher& mesh);

}  // namespace isopatch
