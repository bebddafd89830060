// The octree as the mesher sees it (cell_partition.hpp): shared faces, shared corners, levels.
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "partition/octree_partitioner.hpp"

namespace isopatch {
namespace {

CellPartition build_octree(const std::string& name, int start, int limit) {
  const SurfacePtr surface = catalogue_surface(name);
  PartitionSettings settings;
  settings.surface_depth = start;
  settings.max_depth = limit;
  OctreePartitioner octree(*surface, surface->box(), settings);
  return octree.build();
}

class CellPartitionOfOctree : public ::testing::TestWithParam<std::string> {};

// A closed surface inside its box: every face that holds a loop side is shared by exactly two cells,
// which traverse the sides on it in opposite directions. Nothing else makes the patches close up.
TEST_P(CellPartitionOfOctree, EveryCrossedFaceIsSharedByTwoCellsTraversingItOppositely) {
  const CellPartition p = build_octree(GetParam(), 3, 6);
  ASSERT_FALSE(p.cells.empty());
  std::map<std::uint32_t, std::map<std::uint32_t, std::set<std::pair<std::uint32_t, std::uint32_t>>>> sides;
  for (std::uint32_t c = 0; c < p.cells.size(); ++c) {
    const PartitionCell& cell = p.cells[c];
    EXPECT_GE(cell.level, p.start_level);
    EXPECT_GT(cell.size, 0.0);
    for (const CellLoop& loop : cell.loops) {
      ASSERT_EQ(loop.corners.size(), loop.side_faces.size());
      for (std::size_t k = 0; k < loop.corners.size(); ++k) {
        ASSERT_LT(loop.corners[k], p.corners.size());
        ASSERT_LT(loop.side_faces[k], p.faces.size());
        sides[loop.side_faces[k]][c].insert({loop.corners[k], loop.corners[next(k, loop.corners.size())]});
      }
    }
  }
  EXPECT_EQ(sides.size(), p.faces.size());  // every face listed holds a side
  for (const auto& [f, by_cell] : sides) {
    const CellFace& face = p.faces[f];
    ASSERT_EQ(by_cell.size(), 2u) << "face " << f;
    EXPECT_EQ(face.cells[0], by_cell.begin()->first);
    EXPECT_EQ(face.cells[1], std::next(by_cell.begin())->first);
    std::set<std::pair<std::uint32_t, std::uint32_t>> reversed;
    for (const auto& [a, b] : std::next(by_cell.begin())->second) reversed.insert({b, a});
    EXPECT_EQ(by_cell.begin()->second, reversed) << "face " << f;
    // Axis-aligned faces: the corners of every side lie in the face's plane exactly.
    ASSERT_GE(face.axis, 0);
    for (const auto& [a, b] : reversed) {
      EXPECT_EQ(p.corners[a].position[face.axis], face.region.lo[face.axis]);
      EXPECT_EQ(p.corners[b].position[face.axis], face.region.lo[face.axis]);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Closed, CellPartitionOfOctree, ::testing::Values("torus", "tanglecube", "genus2"),
                         [](const auto& param_info) { return param_info.param; });

TEST(OctreePartitioner, RefinesWhatItIsAskedToAndStartsFinerUpToItsLimit) {
  const SurfacePtr sphere = catalogue_surface("sphere");
  PartitionSettings settings;
  settings.surface_depth = 2;
  settings.max_depth = 4;
  OctreePartitioner octree(*sphere, sphere->box(), settings);
  const CellPartition coarse = octree.build();
  ASSERT_FALSE(coarse.cells.empty());
  EXPECT_EQ(coarse.start_level, 2);
  const std::vector<std::size_t> first{0};
  octree.split(first);
  const CellPartition split = octree.build();
  int deeper = 0;
  for (const PartitionCell& cell : split.cells) deeper += cell.level > 2;
  EXPECT_GT(deeper, 0);
  EXPECT_TRUE(octree.start_finer());
  EXPECT_EQ(octree.build().start_level, 3);
  EXPECT_TRUE(octree.start_finer());
  EXPECT_FALSE(octree.start_finer());  // at the limit
  EXPECT_EQ(octree.max_level(), 4);
}

TEST(OctreeDepths, FollowTheWantedCellLength) {
  const Box box{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
  OctreeDepthRequest r;
  r.cell_length = 2.0 / 8.0;  // the root is a little larger than the box: depth 3 is at most that
  const OctreeDepths d = plan_octree_depths(box, r);
  EXPECT_EQ(d.limit, r.max_depth);
  EXPECT_GE(d.start, 3);
  r.cell_length = 1e-6;  // far below the finest cells: clamped, and the limit raised when asked
  EXPECT_EQ(plan_octree_depths(box, r).start, r.max_depth);
  r.raise_limit_by = 3;
  EXPECT_EQ(plan_octree_depths(box, r).limit, kOctreeDepthLimit);
}

}  // namespace
}  // namespace isopatch
