// The refinement of a base made of pieces, each on its own function, meeting along curves whose points
// the caller gives (refine_pieces, as composite surfaces use it): the curve points kept exactly, every
// other point on its own piece, pieces kept per triangle; an edge between pieces off any curve fails the
// guard; malformed pieces refused.
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "mesh_checks.hpp"
#include "refine/refine_mesh.hpp"
#include "test_surfaces.hpp"

namespace isopatch::refine {
namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;

/// A sphere's base cut into two pieces, above and below z = 0 by triangle centroid, each piece on its
/// own (equal) function, and the edges where the pieces meet.
struct TwoPieces {
  SurfacePtr upper = test::sphere();
  SurfacePtr lower = test::sphere();
  Mesh base;
  RefinePieces pieces;
  std::set<Edge> seam;

  TwoPieces() {
    Settings settings;
    settings.refine = 1;
    settings.edge_length = 0.3;
    base = mesh_surface(*upper, settings);
    pieces.functions = {upper.get(), lower.get()};
    std::map<Edge, std::set<std::uint32_t>> sides;
    for (const Triangle& t : base.triangles) {
      const double z = (base.positions[t[0]] + base.positions[t[1]] + base.positions[t[2]]).z();
      const std::uint32_t piece = z >= 0.0 ? 0 : 1;
      pieces.triangle_piece.push_back(piece);
      for (int s = 0; s < 3; ++s) {
        const std::uint32_t a = t[static_cast<std::size_t>(s)], b = t[static_cast<std::size_t>((s + 1) % 3)];
        sides[{std::min(a, b), std::max(a, b)}].insert(piece);
      }
    }
    for (const auto& [edge, on] : sides)
      if (on.size() == 2) seam.insert(edge);
  }
};

TEST(RefinePieces, SeamPointsAreTheCurvesOwnAndEveryOtherPointIsOnItsPiece) {
  TwoPieces two;
  ASSERT_GT(two.seam.size(), 10u);
  // The seam's points: the chord's points pushed onto the unit sphere (a curve on both functions).
  two.pieces.curve_points = [&](std::uint32_t a, std::uint32_t b, int k, std::span<Vec3> out) {
    if (!two.seam.count({a, b})) return false;
    for (int j = 1; j < k; ++j) {
      const double s = static_cast<double>(j) / k;
      out[static_cast<std::size_t>(j - 1)] =
          ((1.0 - s) * two.base.positions[a] + s * two.base.positions[b]).normalized();
    }
    return true;
  };
  RefineParams p;
  p.level = 4;
  const RefineResult r = refine_pieces(two.base, two.pieces, p);
  ASSERT_EQ(r.failed_points, 0u);
  const TopologyReport topology = analyze_topology(r.mesh);
  EXPECT_TRUE(topology.watertight());
  EXPECT_TRUE(topology.manifold());
  EXPECT_TRUE(topology.outward_oriented());
  EXPECT_LT(test::max_vertex_distance(*two.upper, r.mesh), 1e-10);
  ASSERT_EQ(r.triangle_piece.size(), r.mesh.triangle_count());
  ASSERT_EQ(r.vertex_piece.size(), r.mesh.vertex_count());
  for (std::size_t t = 0; t < r.mesh.triangle_count(); ++t)
    EXPECT_EQ(r.triangle_piece[t], two.pieces.triangle_piece[t / 16]);
  // Every seam point is where the curve put it, and no piece's interior holds it; every other vertex of
  // a triangle lies in that triangle's piece.
  std::set<std::uint32_t> on_seam;
  for (const auto& [a, b] : two.seam) {
    on_seam.insert(a);
    on_seam.insert(b);
  }
  std::size_t seam_points = 0;
  for (std::size_t v = 0; v < r.mesh.vertex_count(); ++v) {
    if (r.vertex_piece[v] >= 0) continue;
    ++seam_points;
    if (v < two.base.vertex_count()) {
      EXPECT_TRUE(on_seam.count(static_cast<std::uint32_t>(v)));
      EXPECT_EQ(r.mesh.positions[v], two.base.positions[v]);
    } else {
      EXPECT_NEAR(r.mesh.positions[v].norm(), 1.0, 1e-15);
    }
  }
  EXPECT_EQ(seam_points, on_seam.size() + 3 * two.seam.size());
  for (std::size_t t = 0; t < r.mesh.triangle_count(); ++t)
    for (const std::uint32_t v : r.mesh.triangles[t])
      if (r.vertex_piece[v] >= 0) {
        EXPECT_EQ(static_cast<std::uint32_t>(r.vertex_piece[v]), r.triangle_piece[t]);
      }
  // The regular lattice inside the pieces, good triangles at the seam.
  EXPECT_GE(analyze_valence(r.mesh).share_6, 0.95);
  EXPECT_GE(r.smallest_angle, 20.0);
}

TEST(RefinePieces, AnEdgeBetweenPiecesOffEveryCurveFailsTheGuard) {
  TwoPieces two;
  RefineParams p;
  p.level = 3;
  const RefineResult r = refine_pieces(two.base, two.pieces, p);
  EXPECT_GE(r.failed_points, two.seam.size());
  EXPECT_EQ(r.mesh.vertex_count(), 0u);
  p.level = 1;  // no points are placed, but the seam is still no curve
  EXPECT_GE(refine_pieces(two.base, two.pieces, p).failed_points, two.seam.size());
}

TEST(RefinePieces, RefusesMalformedPieces) {
  TwoPieces two;
  RefineParams p;
  RefinePieces none;
  EXPECT_THROW(refine_pieces(two.base, none, p), InputError);
  RefinePieces null_function = two.pieces;
  null_function.functions[1] = nullptr;
  EXPECT_THROW(refine_pieces(two.base, null_function, p), InputError);
  RefinePieces short_list = two.pieces;
  short_list.triangle_piece.pop_back();
  EXPECT_THROW(refine_pieces(two.base, short_list, p), InputError);
  RefinePieces out_of_range = two.pieces;
  out_of_range.triangle_piece[0] = 2;
  EXPECT_THROW(refine_pieces(two.base, out_of_range, p), InputError);
  RefinePieces short_vertices = two.pieces;
  short_vertices.vertex_piece.assign(two.base.vertex_count() - 1, 0);
  EXPECT_THROW(refine_pieces(two.base, short_vertices, p), InputError);
  RefinePieces vertex_out_of_range = two.pieces;
  vertex_out_of_range.vertex_piece.assign(two.base.vertex_count(), 0);
  vertex_out_of_range.vertex_piece.back() = 2;
  EXPECT_THROW(refine_pieces(two.base, vertex_out_of_range, p), InputError);
  RefinePieces not_finite = two.pieces;
  not_finite.curve_points = [](std::uint32_t, std::uint32_t, int, std::span<Vec3> out) {
    for (Vec3& q : out) q = Vec3::Constant(std::nan(""));
    return true;
  };
  p.level = 2;
  EXPECT_THROW(refine_pieces(two.base, not_finite, p), InputError);
}

}  // namespace
}  // namespace isopatch::refine
