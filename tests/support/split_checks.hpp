#pragma once
// Checks of a mesh made in parts (blocks of one base, tiles by planes) against one process's mesh of the
// same surface: what joining the parts must keep whatever the seams cost.

#include <gtest/gtest.h>
#include <isopatch/metrics.hpp>

namespace isopatch::test {

/// Consistently oriented, no duplicate vertex, one process's Euler characteristic and component count,
/// no self-intersection, every vertex on f = 0 to 1e-9 (q needs its accuracy).
inline void expect_one_process_topology(const QualityReport& q, const QualityReport& one) {
  EXPECT_TRUE(q.topology.consistently_oriented());
  EXPECT_EQ(q.topology.duplicate_vertices, 0U);
  EXPECT_EQ(q.topology.euler_characteristic, one.topology.euler_characteristic);
  EXPECT_EQ(q.topology.components.size(), one.topology.components.size());
  EXPECT_EQ(q.self_intersections.pairs, 0U);
  ASSERT_TRUE(q.accuracy);
  EXPECT_LT(q.accuracy->vertex_distance.max, 1e-9);
}

}  // namespace isopatch::test
