// Blocks of a base refined apart and put together (isopatch/blocks.hpp): the same mesh as one process
// with one block; with several, watertight across the seams, every seam point made the same by both
// blocks, on f = 0, of the same topology and nearly the same quality.
#include <gtest/gtest.h>

#include <isopatch/blocks.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <vector>

namespace isopatch {
namespace {

Settings torus_settings() {
  Settings s;
  s.refine = 4;
  s.edge_length = 0.05;
  return s;
}

/// The torus's base cut into `count` blocks, every block refined (in reverse order).
struct BlockedTorus {
  SurfacePtr torus = catalogue_surface("torus");
  Settings settings = torus_settings();
  BlockBase base = block_base(*torus, settings);
  BlockPlan plan;
  std::vector<BlockMesh> blocks;

  explicit BlockedTorus(int count) : plan(plan_blocks(base.base, base.level, count)) {
    for (int b = plan.blocks - 1; b >= 0; --b)
      blocks.push_back(refine_block(*torus, settings, base.base, plan, b));
  }
};

TEST(RefineBlock, OneBlockIsTheMultiresolutionMeshOfOneProcess) {
  const BlockedTorus one(1);
  ASSERT_EQ(one.base.level, 4);
  const Mesh blocked = assemble_blocks(one.plan, one.blocks);
  const Mesh whole = mesh_surface(*one.torus, one.settings);
  EXPECT_EQ(blocked.positions, whole.positions);
  EXPECT_EQ(blocked.triangles, whole.triangles);
}

TEST(RefineBlock, EightBlocksAreWatertightOnTheSurfaceAndAsGoodAsOneProcess) {
  const BlockedTorus eight(8);
  const SurfacePtr& torus = eight.torus;
  std::size_t seam_copies = 0, band = 0;
  for (const BlockMesh& b : eight.blocks) {
    EXPECT_EQ(b.failed_points, 0U);
    seam_copies += b.seam_ids.size();
    band += b.seam_band_vertices;
  }
  EXPECT_GT(seam_copies, 0U);  // the blocks do share seams (assemble_blocks checks every copy's bits)
  const Mesh mesh = assemble_blocks(eight.plan, eight.blocks);
  const QualityReport q = analyze_quality(mesh, torus.get());
  EXPECT_TRUE(q.topology.watertight());
  EXPECT_TRUE(q.topology.consistently_oriented());
  EXPECT_TRUE(q.topology.outward_oriented());
  EXPECT_EQ(q.topology.duplicate_vertices, 0U);
  EXPECT_EQ(q.topology.unreferenced_vertices, 0U);
  EXPECT_EQ(q.topology.euler_characteristic, 0);
  EXPECT_EQ(q.topology.components.size(), 1U);
  EXPECT_EQ(q.self_intersections.pairs, 0U);
  ASSERT_TRUE(q.accuracy);
  EXPECT_LT(q.accuracy->vertex_distance.max, 1e-9);
  const QualityReport one = analyze_quality(mesh_surface(*torus, eight.settings));
  EXPECT_GT(q.valence.share_6, one.valence.share_6 - 0.01);
  EXPECT_GT(q.shape.min_angle.min, 20.0);
  EXPECT_GT(band, 0U);  // the band along seams, reported apart
}

TEST(RefineBlock, TheSameBlockTwiceIsTheSameBytes) {
  const SurfacePtr torus = catalogue_surface("torus");
  const Settings settings = torus_settings();
  const BlockBase base = block_base(*torus, settings);
  const BlockPlan plan = plan_blocks(base.base, base.level, 4);
  const BlockMesh a = refine_block(*torus, settings, base.base, plan, 2);
  const BlockMesh b = refine_block(*torus, settings, base.base, plan, 2);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.seam_positions, b.seam_positions);
}

TEST(RefineBlock, AssemblyRefusesMissingRepeatedOrDisagreeingBlocks) {
  BlockedTorus three(3);
  const BlockPlan& plan = three.plan;
  std::vector<BlockMesh>& blocks = three.blocks;
  EXPECT_THROW(assemble_blocks(plan, std::span<const BlockMesh>(blocks).first(2)), InputError);
  std::vector<BlockMesh> twice = {blocks[0], blocks[0], blocks[1]};
  EXPECT_THROW(assemble_blocks(plan, twice), InputError);
  ASSERT_FALSE(blocks[1].seam_positions.empty());
  blocks[1].seam_positions[0].x() += 1e-12;
  EXPECT_THROW(assemble_blocks(plan, blocks), InputError);
  EXPECT_THROW(refine_block(*three.torus, three.settings, three.base.base, plan, 3), InputError);
}

TEST(RefineBlock, TheBaseRefusesWhatBlocksCannotKeep) {
  const SurfacePtr cube = expression_surface("max(max(abs(x),abs(y)),abs(z))-1",
                                             Box{Vec3(-1.5, -1.5, -1.5), Vec3(1.5, 1.5, 1.5)});
  Settings s;
  s.refine = 2;
  EXPECT_THROW(block_base(*cube, s), SettingError);  // exact creases
  s.method = Method::MarchingCubes;
  EXPECT_THROW(block_base(*catalogue_surface("torus"), s), SettingError);
}

}  // namespace
}  // namespace isopatch
