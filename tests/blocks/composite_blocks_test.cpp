// A composite surface (.ipatch) meshed as blocks (isopatch/blocks.hpp): with one block the mesh of one
// process; with several, watertight across the seams, every curve point the curve's own sample to the
// bit, every vertex on its patch's function, of the same topology and nearly the same quality; the
// plan cuts along patches where it can and never through a corner.
#include <gtest/gtest.h>

#include <isopatch/blocks.hpp>
#include <isopatch/composite_mesh.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "composite_mesher/curve_samples.hpp"
#include "split_checks.hpp"

namespace isopatch {
namespace {

const std::string kCompositeExamples = std::string(ISOPATCH_SOURCE_DIR) + "/examples/";

Settings composite_settings(int level = 3) {
  Settings s;
  s.refine = level;
  s.edge_length = 0.06;
  return s;
}

/// A composite example's base cut into `count` blocks, every block refined (in reverse order).
struct BlockedComposite {
  CompositeModel model;
  Settings settings;
  BlockBase base;
  BlockPlan plan;
  std::vector<BlockMesh> blocks;

  BlockedComposite(const std::string& name, int count, int level)
      : model(read_composite(kCompositeExamples + name)),
        settings(composite_settings(level)),
        base(block_base(model, settings)),
        plan(plan_blocks(base.base, base.level, count, base.patches)) {
    for (int b = plan.blocks - 1; b >= 0; --b)
      blocks.push_back(refine_block(model, base.patches, settings, base.base, plan, b));
  }
};

struct Example {
  const char* file;
  int level;  ///< a level one process keeps on it at edge 0.06
};

void PrintTo(const Example& e, std::ostream* os) {
  *os << e.file;
}

class CompositeBlocks : public ::testing::TestWithParam<Example> {};

TEST_P(CompositeBlocks, OneBlockIsTheMeshOfOneProcess) {
  const BlockedComposite one(GetParam().file, 1, GetParam().level);
  ASSERT_EQ(one.base.level, GetParam().level);
  ASSERT_FALSE(one.base.patches.triangle_patch.empty());
  const Mesh blocked = assemble_blocks(one.plan, one.blocks);
  const Mesh whole = mesh_composite(one.model, one.settings);
  EXPECT_EQ(blocked.positions, whole.positions);
  EXPECT_EQ(blocked.triangles, whole.triangles);
}

TEST_P(CompositeBlocks, SixBlocksAreWatertightWithTheCurvesOwnPointsAndAsGoodAsOneProcess) {
  const BlockedComposite six(GetParam().file, 6, GetParam().level);
  std::size_t seam_copies = 0;
  for (const BlockMesh& b : six.blocks) {
    EXPECT_EQ(b.failed_points, 0U);
    EXPECT_TRUE(b.kept);
    seam_copies += b.seam_ids.size();
  }
  EXPECT_GT(seam_copies, 0U);  // assemble_blocks checks every copy's bits against its owner's
  const Mesh mesh = assemble_blocks(six.plan, six.blocks);
  const Mesh whole = mesh_composite(six.model, six.settings);
  EXPECT_EQ(mesh.vertex_count(), whole.vertex_count());
  const QualityReport q = analyze_quality(mesh, six.model.surface().get());
  const QualityReport one = analyze_quality(whole, six.model.surface().get());
  EXPECT_TRUE(q.topology.watertight());
  EXPECT_TRUE(q.topology.outward_oriented());
  test::expect_one_process_topology(q, one);
  EXPECT_GT(q.valence.share_6, one.valence.share_6 - 0.02);
  // Most seams run along curves, whose points one process holds too.
  EXPECT_GT(q.shape.min_angle.min, std::min(24.0, one.shape.min_angle.min - 1.0));

  // Every curve's samples at level times its base segments between its base samples are vertices, bit
  // for bit (no vertex is repeated, above): both blocks beside a curve edge took the curve's own points.
  std::vector<std::array<double, 3>> positions;
  for (const Vec3& p : mesh.positions) positions.push_back({p.x(), p.y(), p.z()});
  std::sort(positions.begin(), positions.end());
  const Composite& c = six.model.composite();
  std::size_t curve_points = 0;
  for (std::size_t i = 0; i < c.curves.size(); ++i) {
    if (six.base.patches.curve_vertices[i].empty()) continue;
    const std::vector<Vec3> samples = sample_curve(c, i, six.base.patches.curve_segments[i] * six.base.level);
    for (std::size_t m = 0; m < samples.size(); ++m) {
      if (m % static_cast<std::size_t>(six.base.level) == 0) continue;  // a base sample
      const Vec3& p = samples[m];
      EXPECT_TRUE(
          std::binary_search(positions.begin(), positions.end(), std::array<double, 3>{p.x(), p.y(), p.z()}));
      ++curve_points;
    }
  }
  EXPECT_GT(curve_points, 0U);
}

TEST(CompositeBlocks, PlansCutAlongPatchesAndNeverThroughACorner) {
  const CompositeModel model = read_composite(kCompositeExamples + "rounded_box.ipatch");
  const BlockBase base = block_base(model, composite_settings());
  const std::size_t triangles = base.base.triangle_count();
  for (const int count : {2, 6, 20, 60}) {
    const BlockPlan plan = plan_blocks(base.base, base.level, count, base.patches);
    // Patches split between blocks: at most one per cut.
    std::map<std::uint32_t, std::set<std::uint32_t>> blocks_of_patch;
    for (std::size_t t = 0; t < triangles; ++t)
      blocks_of_patch[base.patches.triangle_patch[t]].insert(plan.triangle_block[t]);
    std::size_t split = 0;
    for (const auto& [patch, in] : blocks_of_patch) split += in.size() - 1;
    EXPECT_LE(split, static_cast<std::size_t>(count - 1));
    // Blocks within half a block of the even share.
    for (const std::uint64_t n : plan.triangle_count)
      EXPECT_NEAR(static_cast<double>(n) / (base.level * base.level), static_cast<double>(triangles) / count,
                  0.5 * static_cast<double>(triangles) / count + 12.0);
    // A corner's triangles of one patch are in one block.
    for (const auto& curve : base.patches.curve_vertices) {
      if (curve.empty()) continue;
      for (const std::uint32_t corner : {curve.front(), curve.back()}) {
        std::map<std::uint32_t, std::set<std::uint32_t>> around;
        for (std::size_t t = 0; t < triangles; ++t)
          for (const std::uint32_t v : base.base.triangles[t])
            if (v == corner) around[base.patches.triangle_patch[t]].insert(plan.triangle_block[t]);
        for (const auto& [patch, in] : around) EXPECT_EQ(in.size(), 1U);
      }
    }
  }
  // A base of one function is cut as before: evenly along the Morton curve.
  const BlockPlan plain = plan_blocks(base.base, base.level, 6);
  for (const std::uint64_t n : plain.triangle_count)
    EXPECT_NEAR(static_cast<double>(n) / (base.level * base.level), static_cast<double>(triangles) / 6, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Examples, CompositeBlocks,
                         ::testing::Values(Example{"cube.ipatch", 3}, Example{"rounded_box.ipatch", 3},
                                           Example{"octahedron_blend.ipatch", 2}));

TEST(CompositeBlocks, RefusesPatchesOfAnotherBaseAndPartitionSettings) {
  const CompositeModel model = read_composite(kCompositeExamples + "cube.ipatch");
  const Settings settings = composite_settings();
  const BlockBase base = block_base(model, settings);
  const BlockPlan plan = plan_blocks(base.base, base.level, 2, base.patches);
  BasePatches wrong = base.patches;
  wrong.triangle_patch.pop_back();
  EXPECT_THROW(refine_block(model, wrong, settings, base.base, plan, 0), InputError);
  wrong = base.patches;
  wrong.triangle_patch[0] = 1000;
  EXPECT_THROW(refine_block(model, wrong, settings, base.base, plan, 0), InputError);
  wrong = base.patches;
  wrong.curve_segments[0] = 1 << 20;
  EXPECT_THROW(refine_block(model, wrong, settings, base.base, plan, 0), InputError);
  Settings region = settings;
  region.region = {HalfSpace{1.0, 0.0, 0.0, -0.5}};
  EXPECT_THROW(block_base(model, region), SettingError);
  Settings octree = settings;
  octree.max_depth = 3;
  EXPECT_THROW(block_base(model, octree), SettingError);
  BasePatches far = base.patches;
  far.curve_vertices[0].back() = static_cast<std::uint32_t>(base.base.vertex_count());
  EXPECT_THROW(plan_blocks(base.base, base.level, 2, far), InputError);
  BasePatches short_patches = base.patches;
  short_patches.triangle_patch.pop_back();
  EXPECT_THROW(plan_blocks(base.base, base.level, 2, short_patches), InputError);
  EXPECT_THROW(plan_blocks(base.base, base.level, static_cast<int>(base.base.triangle_count()), base.patches),
               InputError);  // a block would be empty: the corners keep their triangles together
}

Box crease_box() {
  return Box{Vec3(-1.5, -1.5, -1.5), Vec3(1.5, 1.5, 1.5)};
}

/// A formula with exact creases (a CSG shape) cut into `count` blocks, every block refined.
struct BlockedCreases {
  SurfacePtr shape;
  Settings settings;
  std::shared_ptr<const CreasedPieces> pieces;
  BlockBase base;
  BlockPlan plan;
  std::vector<BlockMesh> blocks;

  BlockedCreases(const std::string& formula, int count) : shape(resolve_surface(formula, crease_box())) {
    settings.edge_length = 0.06;
    settings.refine = 2;  // the automatic level keeps level 1 on these shapes (see docs/distributed.md)
    settings.box = crease_box();
    pieces = creased_pieces(*shape, settings);
    if (!pieces) return;
    base = block_base(*pieces, settings);
    plan = plan_blocks(base.base, base.level, count, base.patches);
    for (int b = plan.blocks - 1; b >= 0; --b)
      blocks.push_back(refine_block(*pieces, base.patches, settings, base.base, plan, b));
  }
};

// A cube with a round hole through it: 12 + 2 creases, genus 1. Written as the complement of a union:
// max(box, hole) is a smooth solid capped by planes, which one process meshes as its cut surface closed
// by caps (docs/lattices.md) while blocks mesh the general crease path's pieces; this spelling keeps
// both on the general path.
constexpr const char* kHoledCube = "-min(1-max(max(abs(x),abs(y)),abs(z)), sqrt(x^2+y^2)-0.5)";

TEST(CreaseBlocks, OneBlockIsTheMeshOfOneProcessAlongTheCreases) {
  const BlockedCreases one(kHoledCube, 1);
  ASSERT_TRUE(one.pieces);
  ASSERT_FALSE(one.base.patches.triangle_patch.empty());
  const Mesh blocked = assemble_blocks(one.plan, one.blocks);
  const Mesh whole = mesh_surface(*one.shape, one.settings);
  EXPECT_EQ(blocked.positions, whole.positions);
  EXPECT_EQ(blocked.triangles, whole.triangles);
}

TEST(CreaseBlocks, EightBlocksKeepTheCreasesAndCornersWatertightAndAsGoodAsOneProcess) {
  const BlockedCreases eight(kHoledCube, 8);
  ASSERT_TRUE(eight.pieces);
  std::size_t seam_copies = 0;
  for (const BlockMesh& b : eight.blocks) {
    EXPECT_EQ(b.failed_points, 0U);
    seam_copies += b.seam_ids.size();
  }
  EXPECT_GT(seam_copies, 0U);
  const Mesh mesh = assemble_blocks(eight.plan, eight.blocks);
  const QualityReport q = analyze_quality(mesh, eight.shape.get());
  const QualityReport one = analyze_quality(mesh_surface(*eight.shape, eight.settings), eight.shape.get());
  EXPECT_TRUE(q.topology.watertight());
  EXPECT_TRUE(q.topology.consistently_oriented());
  EXPECT_EQ(q.topology.duplicate_vertices, 0U);
  EXPECT_EQ(q.topology.euler_characteristic, 0);
  EXPECT_EQ(q.topology.euler_characteristic, one.topology.euler_characteristic);
  EXPECT_EQ(q.self_intersections.pairs, 0U);
  ASSERT_TRUE(q.accuracy);
  EXPECT_LT(q.accuracy->vertex_distance.max, 1e-9);
  EXPECT_GT(q.shape.min_angle.min, std::min(24.0, one.shape.min_angle.min - 1.0));
  // The cube's 8 corners are vertices, and every vertex near a cube edge (away from the hole) is on it.
  std::size_t on_edges = 0;
  for (const Vec3& corner : {Vec3(1, 1, 1), Vec3(-1, 1, 1), Vec3(1, -1, 1), Vec3(-1, -1, 1), Vec3(1, 1, -1),
                             Vec3(-1, 1, -1), Vec3(1, -1, -1), Vec3(-1, -1, -1)})
    EXPECT_TRUE(std::any_of(mesh.positions.begin(), mesh.positions.end(),
                            [&](const Vec3& p) { return (p - corner).norm() < 1e-12; }));
  for (const Vec3& p : mesh.positions) {
    Vec3 a = p.cwiseAbs();
    std::sort(a.data(), a.data() + 3);
    if (a[1] > 1.0 - 1e-3) {
      EXPECT_NEAR(a[1], 1.0, 1e-12);
      ++on_edges;
    }
  }
  EXPECT_GT(on_edges, 100U);
}

TEST(CreaseBlocks, SmoothFormulasAndCreasesOffHaveNoPieces) {
  Settings settings;
  settings.box = crease_box();
  EXPECT_FALSE(creased_pieces(*resolve_surface("x^2+y^2+z^2-1", settings.box), settings));
  settings.creases = Creases::Off;
  EXPECT_FALSE(creased_pieces(*resolve_surface(kHoledCube, settings.box), settings));
  // block_base() of the surface itself says where the pieces come from.
  settings.creases = Creases::Automatic;
  EXPECT_THROW(block_base(*resolve_surface(kHoledCube, settings.box), settings), SettingError);
}

}  // namespace
}  // namespace isopatch
