#pragma once
// Invariant checks on a Partition, shared by the partition tests.

#include "partition/partition.hpp"

#include <isopatch/surface.hpp>

namespace isopatch::test {

/// Expects (gtest) every invariant the mesher relies on:
/// - loops are closed, have >= 3 distinct corners and one side face per side, each face a face of the
///   leaf's cell containing the segments of both its corners;
/// - each directed side appears once, and its reverse appears exactly once, in another leaf, on the
///   same face (watertight and consistently oriented);
/// - each crossing is listed by exactly the leaves whose cell has its segment as an edge, i.e. by the
///   4 leaves around an interior edge;
/// - crossings lie on f = 0 to 1e-12 cell sizes (f < 0 just before them along their direction, f >= 0
///   just after), inside their segment, with the direction from the negative end to the positive one;
/// - Simple leaves have one loop, oriented along grad f (Newell normal).
void expect_partition_invariants(const Surface& surface, const Partition& partition);

/// Whether the segment lies in the (square) face: on its plane, within its extent.
bool segment_on_face(const SegmentKey& s, const FaceId& f);

/// Euler characteristic V - E + F of the polygon complex formed by the loops (V crossings, E distinct
/// sides, F loops): 2 - 2 genus for a closed surface meshed with disk patches.
long euler_characteristic(const Partition& partition);

}  // namespace isopatch::test
