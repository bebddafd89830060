// Edge splits and collapses of the surface-bound clean-up (one run's state: remesh_run.hpp).
#pragma once

#include <cstddef>
#include <cstdint>

#include "remesh/block_edits.hpp"
#include "remesh/remesh_run.hpp"

namespace isopatch::cleanup {

/// Splits a-b at its midpoint moved onto f = 0 into vertex slot m and triangle slots t, t + 1 (from
/// EditableMesh::add_split_slots) when the four new triangles are valid. Writes only the rings of a
/// and b and the new slots (far-apart calls may run at once; callers count the splits).
bool try_split(RemeshRun& run, std::uint32_t a, std::uint32_t b, std::uint32_t m, std::uint32_t t);

/// Splits the edges longer than kSplitFactor times their size, the longest first within each block
/// (block_edits.hpp); edge k of the list has its own new slots, so the numbering does not depend on
/// the order the blocks ran in.
void split_long_edges(RemeshRun& run);

/// try_split on the listed edges by blocks (block_edits.hpp; `longest`: the longest edge); the count.
std::size_t split_listed(RemeshRun& run, const EdgeList& edges, double longest);

/// Collapses a into b (or b into a when a is locked); `max_length` bounds the new edges (callers count
/// the collapses: this writes only the rings of a and b, so far-apart calls may run at once). Two locked
/// vertices: along their boundary edge (try_collapse_boundary). A `repair` may leave a corner of the cut
/// one triangle (fewest), a routine collapse never.
bool try_collapse(RemeshRun& run, std::uint32_t a, std::uint32_t b, double max_length, bool repair = false);

/// Merges a boundary vertex that may slide (a, else b) into its neighbour along their boundary edge, on
/// the same box face; the neighbour keeps its position, so the cut stays on the box.
bool try_collapse_boundary(RemeshRun& run, std::uint32_t a, std::uint32_t b, double max_length);

/// Collapses the edges shorter than collapse_factor() times their size, the shortest first within each
/// block (block_edits.hpp); adds the collapses to run.stats.
void collapse_short_edges(RemeshRun& run);

}  // namespace isopatch::cleanup
