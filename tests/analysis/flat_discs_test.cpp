// flat_disc (src/analysis/flat_discs.hpp), the proof that lets the self-intersection check skip every
// pair inside a patch: it holds for grids, annuli, islands in holes and patches that touch themselves at
// a vertex, never where a projection covers a point twice (a disc pierced by another, a disc stacked on
// another, an island over a rim, wedges nested at a vertex), and every patch it proves on folded meshes
// meets itself only where it shares (checked with CGAL on thousands of patches).
#include <isopatch/self_intersection.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "analysis/flat_discs.hpp"
#include "analysis/flat_fans.hpp"
#include "analysis/triangle_tree.hpp"
#include "analysis_meshes.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace flat_discs_test {
namespace {

/// A grid of n x n vertices over [x0, x1] x [y0, y1] at heights z(x, y), its triangles turning
/// counter-clockwise seen from +z; triangles whose centre `keep` rejects are left out.
Mesh grid(
    int n, double x0, double y0, double x1, double y1, const std::function<double(double, double)>& z,
    const std::function<bool(double, double)>& keep = [](double, double) { return true; }) {
  Mesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = x0 + (x1 - x0) * i / (n - 1.0), y = y0 + (y1 - y0) * j / (n - 1.0);
      m.positions.emplace_back(x, y, z(x, y));
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const auto v = static_cast<std::uint32_t>(j * n + i), w = static_cast<std::uint32_t>(n);
      const double cx = x0 + (x1 - x0) * (i + 0.5) / (n - 1.0), cy = y0 + (y1 - y0) * (j + 0.5) / (n - 1.0);
      if (!keep(cx, cy)) continue;
      m.triangles.push_back({v, v + 1, v + w + 1});
      m.triangles.push_back({v, v + w + 1, v + w});
    }
  return m;
}

double flat(double, double) {
  return 0.0;
}

/// a with b's vertices and triangles appended.
Mesh joined(Mesh a, const Mesh& b) {
  const auto offset = static_cast<std::uint32_t>(a.positions.size());
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  for (const Triangle& t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return a;
}

/// flat_disc over the triangles of `mesh` at positions [begin, end) of `order`.
bool proved(const Mesh& mesh, const std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end) {
  const analysis::MeshFans fans = analysis::mesh_fans(mesh);
  std::vector<std::uint32_t> position(mesh.triangles.size(), std::numeric_limits<std::uint32_t>::max());
  for (std::size_t p = 0; p < order.size(); ++p) position[order[p]] = static_cast<std::uint32_t>(p);
  std::uint8_t turns = 0x3F;
  for (std::size_t p = begin; p < end; ++p) turns &= fans.triangle_turns[order[p]];
  const analysis::OrderedTriangles ordered{&mesh, &fans, &order, position.data()};
  return analysis::flat_disc(ordered, static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end),
                             turns);
}

/// flat_disc over all the triangles of `mesh`, in its order.
bool proved(const Mesh& mesh) {
  std::vector<std::uint32_t> order(mesh.triangles.size());
  for (std::uint32_t t = 0; t < order.size(); ++t) order[t] = t;
  return proved(mesh, order, 0, order.size());
}

/// The whole check agrees with CGAL on `mesh`.
void agrees_with_cgal(const Mesh& mesh) {
  EXPECT_EQ(find_self_intersections(mesh, 100000).pairs, test::count_self_intersections(mesh, 100000));
}

TEST(FlatDiscs, GridsAnnuliAndTheirMirrorImagesAreProved) {
  const Mesh square = grid(12, 0, 0, 1, 1, flat);
  EXPECT_TRUE(proved(square));
  const auto outside_hole = [](double x, double y) { return !(x > 0.3 && x < 0.7 && y > 0.3 && y < 0.7); };
  const Mesh annulus = grid(
      21, 0, 0, 1, 1, [](double x, double y) { return 0.2 * x * y; }, outside_hole);
  EXPECT_TRUE(proved(annulus));
  // Turned over: every triangle clockwise seen from +z, the holes' boundaries the other way round.
  Mesh turned = annulus;
  for (Triangle& t : turned.triangles) std::swap(t[1], t[2]);
  EXPECT_TRUE(proved(turned));
  // A closed surface turns both ways in every projection.
  EXPECT_FALSE(proved(test::icosphere(2)));
}

TEST(FlatDiscs, ADiscPiercedOrCoveredByAnotherIsNot) {
  const Mesh disc = grid(21, 0, 0, 1, 1, flat);
  // A small disc tilted through the large one (its triangles turn the same way seen from +z): its
  // boundary's image lies inside the large one's, apart from it.
  const Mesh pierced =
      joined(disc, grid(7, 0.4, 0.4, 0.6, 0.6, [](double x, double) { return 0.5 * (x - 0.5); }));
  EXPECT_FALSE(proved(pierced));
  EXPECT_GT(find_self_intersections(pierced).pairs, 0U);
  agrees_with_cgal(pierced);
  // The same disc flat above the large one: no intersection, but two triangles over one point.
  const Mesh stacked = joined(disc, grid(7, 0.4, 0.4, 0.6, 0.6, [](double, double) { return 0.2; }));
  EXPECT_FALSE(proved(stacked));
  EXPECT_EQ(find_self_intersections(stacked).pairs, 0U);
  agrees_with_cgal(stacked);
}

TEST(FlatDiscs, AnIslandInAHoleIsProvedAndOneOverTheRimIsNot) {
  const auto outside_hole = [](double x, double y) { return !(x > 0.3 && x < 0.7 && y > 0.3 && y < 0.7); };
  const Mesh annulus = grid(21, 0, 0, 1, 1, flat, outside_hole);
  const Mesh island = joined(annulus, grid(5, 0.4, 0.4, 0.6, 0.6, [](double, double) { return 0.1; }));
  EXPECT_TRUE(proved(island));
  agrees_with_cgal(island);
  // An island larger than the hole, over the rim all round (its boundary crosses none): above the rim,
  // and through it.
  const Mesh over = joined(annulus, grid(9, 0.22, 0.22, 0.78, 0.78, [](double, double) { return 0.1; }));
  EXPECT_FALSE(proved(over));
  agrees_with_cgal(over);
  const Mesh through =
      joined(annulus, grid(9, 0.22, 0.22, 0.78, 0.78, [](double x, double) { return x - 0.5; }));
  EXPECT_FALSE(proved(through));
  EXPECT_GT(find_self_intersections(through).pairs, 0U);
  agrees_with_cgal(through);
}

TEST(FlatDiscs, PatchesTouchingAtAVertexAreProvedUnlessTheirWedgesNest) {
  // Two squares sharing the corner (1, 1) by index: the boundary passes it twice, out and in alternating.
  Mesh corner = joined(grid(5, 0, 0, 1, 1, flat), grid(5, 1, 1, 2, 2, flat));
  const auto shared = static_cast<std::uint32_t>(5 * 5 - 1);  // (1, 1) of the first
  for (std::size_t t = 32; t < corner.triangles.size(); ++t)
    for (std::uint32_t& v : corner.triangles[t])
      if (v == 25) v = shared;  // (1, 1) of the second
  EXPECT_TRUE(proved(corner));
  agrees_with_cgal(corner);
  // Two wedges at one vertex, the second inside the first seen from +z (out, out, in, in around it):
  // above the first, and dipping through it.
  for (const double height : {0.1, -0.1}) {
    Mesh nested;
    nested.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0.5, 0.1, 0.0),
                        Vec3(0.5, 0.4, height)};
    nested.triangles = {{0, 1, 2}, {0, 3, 4}};
    // More of the first wedge's sheet around it, so the patch is more than two triangles.
    nested.positions.emplace_back(0, 1, 0);
    nested.triangles.push_back({0, 2, 5});
    EXPECT_FALSE(proved(nested)) << height;
    agrees_with_cgal(nested);
  }
}

/// The triangles at positions [begin, end) of `order` as a mesh of their own.
Mesh part(const Mesh& m, const std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end) {
  Mesh out;
  out.positions = m.positions;
  for (std::size_t p = begin; p < end; ++p) out.triangles.push_back(m.triangles[order[p]]);
  return out;
}

TEST(FlatDiscs, EveryProvedPatchOfFoldedMeshesMeetsOnlyWhereItShares) {
  std::size_t proofs = 0, refusals = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(seed);
    const Mesh base = seed % 2 == 0 ? test::icosphere(4) : test::parametric_torus(60, 30);
    const Mesh m = test::jittered(base, 150, seed <= 2 ? 0.02 : 0.06, seed);
    const std::vector<std::uint32_t> order = analysis::z_ordered_triangles(m);
    std::mt19937 rng(100 + seed);
    std::uniform_int_distribution<std::size_t> length(64, 400);
    for (int trial = 0; trial < 120; ++trial) {
      const std::size_t n = length(rng);
      const std::size_t begin = std::uniform_int_distribution<std::size_t>(0, order.size() - n)(rng);
      if (!proved(m, order, begin, begin + n)) {
        ++refusals;
        continue;
      }
      ++proofs;
      ASSERT_EQ(test::count_self_intersections(part(m, order, begin, begin + n), 10), 0U)
          << "positions " << begin << " to " << begin + n;
    }
    agrees_with_cgal(m);
  }
  EXPECT_GT(proofs, 100U);
  EXPECT_GT(refusals, 100U);
}

/// Triangles in the subtrees proved flat discs, of the tree over `order`.
std::size_t proved_triangles(const Mesh& m, std::vector<std::uint32_t> order) {
  const analysis::MeshFans fans = analysis::mesh_fans(m);
  analysis::TriangleTree tree(m, std::move(order), &fans.triangle_turns);
  std::vector<std::uint32_t> position(m.triangles.size(), std::numeric_limits<std::uint32_t>::max());
  for (std::size_t p = 0; p < tree.order().size(); ++p)
    position[tree.order()[p]] = static_cast<std::uint32_t>(p);
  const analysis::OrderedTriangles ordered{&m, &fans, &tree.order(), position.data()};
  tree.prove_subtrees(
      [&](std::uint32_t b, std::uint32_t e, std::uint8_t t) { return analysis::flat_disc(ordered, b, e, t); },
      64);
  return tree.proved_triangles();
}

TEST(FlatDiscs, MostOfASmoothMeshIsProvedAndEveryOrderFindsTheSamePairs) {
  // In Z-order, the subtrees of a smooth torus are flat discs; in the order it is written (strips of
  // quads around the tube), none is, and the check falls back to Z-order.
  const Mesh torus = test::parametric_torus(120, 60);
  EXPECT_GT(proved_triangles(torus, analysis::z_ordered_triangles(torus)), torus.triangles.size() * 3 / 4);
  EXPECT_EQ(proved_triangles(torus, analysis::own_order(torus)), 0U);
  EXPECT_TRUE(analysis::keeps_neighbours_together(torus, analysis::own_order(torus)));
  // Folded, in its own order and shuffled (which the check sees is not local): the pairs CGAL finds.
  Mesh folded = test::jittered(torus, 400, 0.05, 9);
  agrees_with_cgal(folded);
  std::mt19937 rng(3);
  std::shuffle(folded.triangles.begin(), folded.triangles.end(), rng);
  EXPECT_FALSE(analysis::keeps_neighbours_together(folded, analysis::own_order(folded)));
  agrees_with_cgal(folded);
}

}  // namespace
}  // namespace flat_discs_test
}  // namespace isopatch
