// A lattice capped by planes meshed as blocks (isopatch/blocks.hpp, CappedPieces): every cut surface
// refined in blocks with the planes as its region, the parts closed by their caps afterwards. With one
// block the mesh of one process to the bit; with several, closed, manifold, outward, free of
// self-intersections, its creases exactly on the planes, and the topology and nearly the angles of one
// process. Sheets, shells and other formulas get the parts one process meshes them as.
#include <gtest/gtest.h>

#include <isopatch/blocks.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace isopatch {
namespace {

constexpr const char* kGyroid = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)";
constexpr const char* kCube = "max(max(abs(x),abs(y)),abs(z))";

std::string capped_gyroid() {
  return std::string("max(") + kGyroid + "," + kCube + "-pi)";
}

Settings capped_settings() {
  Settings s;
  s.box = Box{Vec3::Constant(-3.4), Vec3::Constant(3.4)};
  s.edge_length = 0.2;
  s.refine = 2;
  return s;
}

/// A formula's capped pieces, every cut surface cut into `count` blocks refined in reverse order and
/// assembled, and the parts closed.
struct BlockedCapped {
  SurfacePtr shape;
  Settings settings = capped_settings();
  std::shared_ptr<const CappedPieces> pieces;
  std::size_t seam_copies = 0;
  Mesh mesh;

  BlockedCapped(const std::string& formula, int count)
      : shape(resolve_surface(formula, capped_settings().box)) {
    pieces = capped_pieces(*shape, settings);
    if (!pieces) return;
    std::vector<Mesh> cuts;
    for (std::size_t c = 0; c < capped_cut_parts(*pieces).size(); ++c) {
      const BlockBase base = block_base(*pieces, c, settings);
      const BlockPlan plan = plan_blocks(base.base, base.level, count);
      std::vector<BlockMesh> blocks;
      for (int b = plan.blocks - 1; b >= 0; --b) {
        blocks.push_back(refine_block(*pieces, c, settings, base.base, plan, b));
        EXPECT_EQ(blocks.back().failed_points, 0U);
        seam_copies += blocks.back().seam_ids.size();
      }
      cuts.push_back(assemble_blocks(plan, blocks));
    }
    mesh = close_capped(*pieces, std::move(cuts), settings);
  }
};

TEST(CappedBlocks, OneBlockIsTheMeshOfOneProcess) {
  const BlockedCapped one(capped_gyroid(), 1);
  ASSERT_TRUE(one.pieces);
  const Mesh whole = mesh_surface(*one.shape, one.settings);
  EXPECT_EQ(one.mesh.positions, whole.positions);
  EXPECT_EQ(one.mesh.triangles, whole.triangles);
}

TEST(CappedBlocks, FourBlocksAreAClosedPartAlongExactCreasesAsGoodAsOneProcess) {
  const BlockedCapped four(capped_gyroid(), 4);
  ASSERT_TRUE(four.pieces);
  EXPECT_GT(four.seam_copies, 0U);
  const QualityReport q = analyze_quality(four.mesh, nullptr);
  const QualityReport one = analyze_quality(mesh_surface(*four.shape, four.settings), nullptr);
  EXPECT_TRUE(q.topology.watertight());
  EXPECT_TRUE(q.topology.manifold());
  EXPECT_TRUE(q.topology.consistently_oriented());
  EXPECT_TRUE(q.topology.outward_oriented());
  EXPECT_EQ(q.topology.euler_characteristic, one.topology.euler_characteristic);
  EXPECT_EQ(q.topology.components.size(), one.topology.components.size());
  EXPECT_EQ(q.topology.genus, one.topology.genus);
  EXPECT_EQ(q.self_intersections.pairs, 0U);
  EXPECT_GT(q.shape.min_angle.min, std::min(25.0, one.shape.min_angle.min - 1.0));
  // Nothing outside the part, and its caps and creases exactly on its planes.
  std::size_t on_planes = 0;
  for (const Vec3& p : four.mesh.positions) {
    EXPECT_LE(p.cwiseAbs().maxCoeff(), std::numbers::pi);
    on_planes += p.cwiseAbs().maxCoeff() == std::numbers::pi ? 1 : 0;
  }
  EXPECT_GT(on_planes, four.mesh.vertex_count() / 50);
}

TEST(CappedBlocks, SheetsAndShellsHaveThePartsOneProcessMeshesThemAs) {
  const Settings settings = capped_settings();
  const auto pieces = [&](const std::string& formula) {
    return capped_pieces(*resolve_surface(formula, settings.box), settings);
  };
  // A capped sheet: one part whose cut is the sheet's two walls.
  const auto sheet = pieces(std::string("max(abs(") + kGyroid + ")-0.3," + kCube + "-pi)");
  ASSERT_TRUE(sheet);
  EXPECT_EQ(capped_part_count(*sheet), 1U);
  EXPECT_EQ(capped_cut_parts(*sheet), (std::vector<std::size_t>{0, 0}));
  // A shell: the outer polyhedron's caps (no cut), then the hollows.
  const auto shell = pieces(std::string("min(max(") + kGyroid + "," + kCube + "-pi),max(" + kCube +
                            "-pi,2.8-" + kCube + "))");
  ASSERT_TRUE(shell);
  EXPECT_EQ(capped_part_count(*shell), 2U);
  EXPECT_EQ(capped_cut_parts(*shell), (std::vector<std::size_t>{1}));
  // Not capped: a smooth surface, an open lattice; creases off.
  EXPECT_FALSE(pieces("x^2+y^2+z^2-1"));
  EXPECT_FALSE(pieces(kGyroid));
  Settings off = settings;
  off.creases = Creases::Off;
  EXPECT_FALSE(capped_pieces(*resolve_surface(capped_gyroid(), settings.box), off));
}

TEST(CappedBlocks, RefusesFramesAndCutsItDoesNotHave) {
  Settings settings = capped_settings();
  const SurfacePtr shape = resolve_surface(capped_gyroid(), settings.box);
  const auto pieces = capped_pieces(*shape, settings);
  ASSERT_TRUE(pieces);
  EXPECT_THROW(block_base(*pieces, 1, settings), InputError);
  EXPECT_THROW(close_capped(*pieces, {}, settings), InputError);
  settings.frame = Frame{30.0, 20.0, 10.0};
  EXPECT_THROW(capped_pieces(*shape, settings), SettingError);
}

}  // namespace
}  // namespace isopatch
