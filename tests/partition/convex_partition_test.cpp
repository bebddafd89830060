// Partitions of general convex cells (convex_partitioner.hpp, convex_partition.hpp): shared faces,
// shared corners, faces that meet several finer faces, and the checks of a caller's cells.
#include <isopatch/error.hpp>
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "partition/convex_partitioner.hpp"

namespace isopatch {
namespace {

const Box kBox{Vec3(-0.5, -0.5, -0.5), Vec3(2.5, 1.5, 1.5)};

/// The axis-aligned box [lo, hi] as six planes.
std::vector<CellPlane> box_cell(const Vec3& lo, const Vec3& hi) {
  return {make_cell_plane(-1, 0, 0, lo.x()), make_cell_plane(1, 0, 0, -hi.x()),
          make_cell_plane(0, -1, 0, lo.y()), make_cell_plane(0, 1, 0, -hi.y()),
          make_cell_plane(0, 0, -1, lo.z()), make_cell_plane(0, 0, 1, -hi.z())};
}

/// Every loop side's face names the cell, and a side on a face with two cells is traversed once in
/// each direction; every corner of a loop lies on the face planes of the sides it joins.
void expect_consistent(const CellPartition& p) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::uint32_t c = 0; c < p.cells.size(); ++c)
    for (const CellLoop& loop : p.cells[c].loops)
      for (std::size_t k = 0; k < loop.corners.size(); ++k) {
        const CellFace& face = p.faces[loop.side_faces[k]];
        EXPECT_TRUE(face.cells[0] == c || face.cells[1] == c);
        const std::uint32_t a = loop.corners[k], b = loop.corners[(k + 1) % loop.corners.size()];
        ++directed[{a, b}];
        for (std::uint32_t v : {a, b}) {
          const Vec3 d = p.corners[v].position - p.corners[loop.corners[k]].position;
          EXPECT_LE(std::abs(d.dot(face.normal)), 1e-12);
        }
      }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    const auto reverse = directed.find({edge.second, edge.first});
    // Sides on the outer boundary have no reverse; all others have exactly one.
    if (reverse != directed.end()) {
      EXPECT_EQ(reverse->second, 1);
    }
  }
}

TEST(ConvexPartition, TwoCellsCutByAnObliquePlaneShareTheirSide) {
  const SurfacePtr f = resolve_surface("z - 0.5 - 0.1*x", kBox, {});
  std::vector<CellPlane> a = box_cell(Vec3::Zero(), Vec3::Ones()), b = a;
  a.push_back(make_cell_plane(1, 0.3, 0.2, -0.6));
  b.push_back(make_cell_plane(-1, -0.3, -0.2, 0.6));
  ConvexPartitioner partitioner = ConvexPartitioner::given_cells(*f, kBox, {a, b}, {});
  const CellPartition p = partitioner.build();
  ASSERT_EQ(p.cells.size(), 2u);
  for (const PartitionCell& cell : p.cells) {
    EXPECT_EQ(cell.reason, ComplexReason::None);
    ASSERT_EQ(cell.loops.size(), 1u);
    EXPECT_FALSE(cell.planes.empty());
  }
  // The oblique plane crosses the faces y = 0 and y = 1: each cell's loop is a quadrilateral, two of
  // whose corners (on the cut's edges) are shared.
  EXPECT_EQ(p.cells[0].loops[0].corners.size(), 4u);
  EXPECT_EQ(p.cells[1].loops[0].corners.size(), 4u);
  EXPECT_EQ(p.corners.size(), 6u);
  int shared = 0;
  for (const CellFace& face : p.faces) {
    if (face.cells[1] == kNoCell) continue;
    ++shared;
    EXPECT_EQ(face.axis, -1);  // the oblique plane
  }
  EXPECT_EQ(shared, 1);
  expect_consistent(p);
}

TEST(ConvexPartition, ACoarseFaceMeetsTwoFinerFaces) {
  // A unit cube next to two cells of half its width: the crossing on the finer cells' shared
  // edge is a corner of the coarse cell too (a flat corner inside its face), so there is no T-junction.
  const SurfacePtr f = resolve_surface("z - 0.5 - 0.05*x - 0.1*y", kBox, {});
  const auto a = box_cell(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const auto b1 = box_cell(Vec3(1, 0, 0), Vec3(2, 0.5, 1));
  const auto b2 = box_cell(Vec3(1, 0.5, 0), Vec3(2, 1, 1));
  ConvexPartitioner partitioner = ConvexPartitioner::given_cells(*f, kBox, {a, b1, b2}, {});
  const CellPartition p = partitioner.build();
  ASSERT_EQ(p.cells.size(), 3u);
  EXPECT_EQ(p.cells[0].loops.at(0).corners.size(), 5u);
  EXPECT_EQ(p.cells[1].loops.at(0).corners.size(), 4u);
  EXPECT_EQ(p.cells[2].loops.at(0).corners.size(), 4u);
  std::set<std::uint32_t> coarse(p.cells[0].loops[0].corners.begin(), p.cells[0].loops[0].corners.end());
  int common = 0;
  for (int c : {1, 2})
    for (std::uint32_t k : p.cells[static_cast<std::size_t>(c)].loops[0].corners)
      common += coarse.count(k) ? 1 : 0;
  EXPECT_EQ(common, 4);  // two corners with each finer cell; the flat corner counted once for each
  expect_consistent(p);
}

TEST(ConvexPartition, SplitsACellByThreePlanes) {
  const SurfacePtr f = resolve_surface("z - 0.5 - 0.05*x - 0.1*y", kBox, {});
  ConvexPartitionerSettings s;
  s.max_level = 2;
  ConvexPartitioner partitioner = ConvexPartitioner::given_cells(
      *f, kBox, {box_cell(Vec3(0, 0, 0), Vec3(1, 1, 1)), box_cell(Vec3(1, 0, 0), Vec3(2, 1, 1))}, s);
  CellPartition p = partitioner.build();
  ASSERT_EQ(p.cells.size(), 2u);
  const std::size_t first = 0;
  partitioner.split(std::span(&first, 1));
  p = partitioner.build();
  EXPECT_EQ(partitioner.leaf_count(), 9u);
  // Four of the eight octants hold the plane z ~ 0.5 (the lower ones at z < 0.5 only near x, y = 0).
  std::size_t fine = 0;
  for (const PartitionCell& cell : p.cells) fine += cell.level == 1 ? 1 : 0;
  EXPECT_GE(fine, 4u);
  // The coarse neighbour now meets two finer faces that hold the surface: a loop of 5 corners.
  EXPECT_EQ(p.cells.back().level, 0);
  EXPECT_EQ(p.cells.back().loops.at(0).corners.size(), 5u);
  expect_consistent(p);
}

TEST(ConvexPartition, GapsAndOverlapsAreInputErrors) {
  const SurfacePtr f = resolve_surface("z - 0.5", kBox, {});
  const auto a = box_cell(Vec3(0, 0, 0), Vec3(1, 1, 1));
  auto message = [&](const std::vector<std::vector<CellPlane>>& cells) {
    try {
      ConvexPartitioner::given_cells(*f, kBox, cells, {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // A neighbour that covers only part of the shared face.
  EXPECT_NE(message({a, box_cell(Vec3(1, 0, 0), Vec3(2, 0.8, 1))}).find("gap"), std::string::npos);
  // Two cells that share volume.
  EXPECT_NE(message({a, box_cell(Vec3(0.5, 0, 0), Vec3(1.5, 1, 1))}).find("overlap"), std::string::npos);
  // A cell with no volume in the box, and no cells at all.
  EXPECT_NE(message({a, box_cell(Vec3(5, 5, 5), Vec3(6, 6, 6))}).find("cell 1"), std::string::npos);
  EXPECT_NE(message({}).find("no cells"), std::string::npos);
  // Cells that meet face to face, and cells that do not touch at all, are fine.
  EXPECT_EQ(message({a, box_cell(Vec3(1, 0, 0), Vec3(2, 1, 1))}), "");
  EXPECT_EQ(message({a, box_cell(Vec3(1.5, 0, 0), Vec3(2, 1, 1))}), "");
}

TEST(ConvexPartition, ClippedLatticeKeepsToTheRegion) {
  // The region z <= 0.3 x + 0.2 over a sphere: every corner lies inside it, some cells are cut by its
  // plane, and the faces on the region's boundary that are not box faces lie on that plane.
  const Box box{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
  const SurfacePtr f = resolve_surface("x^2 + y^2 + z^2 - 0.7", box, {});
  ConvexPartitionerSettings s;
  s.start_level = 3;
  s.max_level = 5;
  const CellPlane region = make_cell_plane(-0.3, 0, 1, -0.2, 0);
  ConvexPartitioner partitioner = ConvexPartitioner::clipped_lattice(*f, box, {region}, s);
  const CellPartition p = partitioner.build();
  ASSERT_FALSE(p.cells.empty());
  std::size_t on_region = 0;
  for (const PartitionCell& cell : p.cells) {
    EXPECT_EQ(cell.level, 3);
    for (const CellPlane& plane : cell.planes) on_region += plane.label == 0 ? 1 : 0;
  }
  EXPECT_GT(on_region, 0u);
  for (const CellCorner& corner : p.corners) EXPECT_LE(region.distance(corner.position), 1e-12);
  for (const CellFace& face : p.faces)
    if (face.cells[1] == kNoCell && face.axis < 0) {
      EXPECT_NEAR(std::abs(face.normal.dot(region.normal)), 1.0, 1e-15);
    }
  expect_consistent(p);
  EXPECT_THROW(ConvexPartitioner::clipped_lattice(*f, box, {make_cell_plane(0, 0, 1, 5, 0)}, s), InputError);
}

}  // namespace
}  // namespace isopatch
