#pragma once
// Whether two triangles of a mesh meet other than in what they share by index: the exact test of each
// pair of the self-intersection check (self_intersection.cpp), and the reference its fuzzer compares the
// whole check with. Two triangles in general position meet iff an edge of one meets the other, since
// each end of the segment where they meet lies on an edge of one of them; every decision is an exact
// orientation sign (exact_predicates.hpp: Shewchuk 1997).

#include <isopatch/mesh.hpp>

namespace isopatch::analysis {

/// Triangles s and t of `mesh` (indices into mesh.positions, none repeated within one) meet other than
/// in what they share by index: without a common vertex, when they touch or cross; with one, when they
/// meet anywhere else; with a common edge, when they lie in one plane on the same side of it (folded
/// flat); with all three, always. *at receives a point where they meet (a vertex of the crossing, or a
/// shared vertex for folded neighbours) when they do.
bool triangles_meet(const Mesh& mesh, const Triangle& s, const Triangle& t, Vec3* at);

}  // namespace isopatch::analysis
