// Splits of long edges of a cut (the boundary where the box or a region plane cuts the surface open) in
// the surface-bound clean-up (one run's state: remesh_run.hpp).
#pragma once

#include <cstddef>
#include <cstdint>

#include "remesh/remesh_run.hpp"

namespace isopatch::cleanup {

/// Splits the boundary edge a - b when both ends lie on one face of the box (exactly) or one plane of the
/// region (to plane_margin()), and on no second one: its midpoint is moved onto the curve where f = 0
/// meets that face or plane (Newton steps within it, at most the edge's length), must stay on that face or
/// plane alone, within the edge's length of both ends, and leave both new triangles valid (triangle_ok).
/// The new vertex is a locked cut vertex that slides on that face or plane. Where a new triangle would not
/// be valid because the edge's triangle is a sliver (its third vertex, not on the cut, within a tenth of
/// the edge of an end, as the mesher leaves where the cut curve turns inside a cell), that vertex is
/// collapsed into the end (try_collapse, with its checks) and the split tried again, `merges` times at
/// most. Writes the rings of a and b, the new slots and the run's sliding lists. False when no split was
/// made (a merge may have been), or with settings.hold_cut.
/// \throw EvaluationError if f or grad f is not finite on the way.
bool try_split_cut_edge(RemeshRun& run, std::uint32_t a, std::uint32_t b, int merges = 4);

/// try_split_cut_edge on every boundary edge longer than kSplitFactor times the target edge
/// (settings.sizes.largest: graded sizes at a cut feature shrink the mesher's cells there already, and
/// caps closing the cut are meshed at the target edge), the longest first
/// (ties by vertex ids), one after the other: the same result for any number of threads. Without it, a
/// cut keeps the spacing the mesher's cells gave it (a chord of several edges where the cut curve turns
/// inside a cell face), since interior splits (split_long_edges) never touch the boundary. Adds the
/// splits to run.stats; returns their number. Follows no paper: the boundary counterpart of the
/// split step of isotropic remeshing (Botsch and Kobbelt 2004).
std::size_t split_long_cut_edges(RemeshRun& run);

}  // namespace isopatch::cleanup
