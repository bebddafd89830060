// The partition on the benchmark surfaces: the invariants that make the assembled mesh closed and
// oriented, and the topology of the loop complex.
#include "partition/partition.hpp"
#include "partition_checks.hpp"
#include "test_surfaces.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <string>

namespace isopatch {
namespace {

struct InvariantCase {
  std::string name;
  SurfacePtr surface;
  long euler;             // 2 - 2 genus
  int resolved_from = 4;  // the depth from which the loops capture the topology
};

std::vector<InvariantCase> cases() {
  return {{"sphere", test::sphere(), 2},
          {"torus", test::torus(), 0},
          {"tanglecube", test::tanglecube(), -8},
          {"genus2", test::genus2(), -2, 5},
          {"small_sphere", test::sphere(0.5, Vec3::Zero(), 1.0), 2}};
}

void print(const std::string& name, int depth, const Partition& p) {
  const PartitionStats& s = p.stats;
  std::cout << name << " depth " << depth << ": leaves " << p.leaves.size() << " simple " << s.simple_leaves
            << " complex " << s.complex_leaves << " (";
  for (int r = 1; r < kComplexReasonCount; ++r)
    if (s.complex_by_reason[r] > 0)
      std::cout << " " << to_string(static_cast<ComplexReason>(r)) << " " << s.complex_by_reason[r];
  std::cout << " ) crossings " << p.crossings.size() << " visited " << s.cells_visited << " pruned(heur) "
            << s.pruned_by_heuristic << " f " << s.value_evaluations << " grad " << s.gradient_evaluations
            << " euler " << test::euler_characteristic(p) << "\n";
}

TEST(Partition, InvariantsOnBenchmarkSurfaces) {
  for (const InvariantCase& c : cases()) {
    for (int depth : {4, 5}) {
      SCOPED_TRACE(c.name + " depth " + std::to_string(depth));
      PartitionSettings settings;
      settings.surface_depth = depth;
      settings.max_depth = depth + 2;
      const Partition p = build_partition(*c.surface, c.surface->box(), settings);
      print(c.name, depth, p);
      ASSERT_FALSE(p.leaves.empty());
      test::expect_partition_invariants(*c.surface, p);
      EXPECT_EQ(p.stats.simple_leaves + p.stats.complex_leaves, p.leaves.size());
      if (depth >= c.resolved_from) {
        EXPECT_EQ(test::euler_characteristic(p), c.euler);
      }
    }
  }
}

// With max_depth == surface_depth the face and cell centres of the leaves are off the finest lattice
// (half-lattice samples); the invariants must still hold.
TEST(Partition, InvariantsWhenLeavesAreAtTheFinestDepth) {
  const auto surface = test::torus();
  PartitionSettings settings;
  settings.surface_depth = 5;
  settings.max_depth = 5;
  const Partition p = build_partition(*surface, surface->box(), settings);
  test::expect_partition_invariants(*surface, p);
  EXPECT_EQ(test::euler_characteristic(p), 0);
}

}  // namespace
}  // namespace isopatch
