// Valence flips with glide chains on a planar grid scrambled by random flips: the chains must lower
// the valence energy below what greedy flips reach (and chains that may borrow below neutral ones),
// never raise it, keep the mesh a valid disk, and undo every chain that finds no lowering flip. On a
// grid large enough for several cubes (flip_blocks.hpp), the blocked flips give one result for any
// number of threads, and cubes of one colour never share a two-ring.
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <optional>
#include <random>
#include <vector>

#include <tbb/task_arena.h>

#include "remesh/block_edits.hpp"
#include "remesh/editable_mesh.hpp"
#include "remesh/flip_blocks.hpp"
#include "remesh/valence_flips.hpp"

namespace isopatch {
namespace {

/// An n x n grid of unit squares in the plane z = 0, each cut by the same diagonal (valence 6 inside).
EditableMesh grid(int n) {
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({double(i), double(j), 0.0});
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return EditableMesh(m, std::vector<Vec3>(m.positions.size(), Vec3(0, 0, 1)));
}

/// True when the two triangles that flipping e would create are counter-clockwise in the plane with
/// no angle under `min_degrees`.
bool flip_keeps_planar_shape(const EditableMesh& m, const EditableMesh::Edge& e, double min_degrees) {
  const auto good = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const Vec3 p[3] = {m.positions[a], m.positions[b], m.positions[c]};
    if ((p[1] - p[0]).cross(p[2] - p[0]).z() <= 0.0) return false;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
      if (std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / 3.141592653589793 < min_degrees) return false;
    }
    return true;
  };
  return !m.adjacent(e.c, e.d) && good(e.a, e.d, e.c) && good(e.b, e.c, e.d);
}

int valence_energy(const EditableMesh& m) {
  int energy = 0;
  for (std::uint32_t v = 0; v < m.vertex_slots(); ++v) {
    if (!m.alive(v)) continue;
    const int d = static_cast<int>(m.valence(v)) - target_valence(m, v);
    energy += d * d;
  }
  return energy;
}

/// The grid with `flips` random valid flips applied (fixed seed).
EditableMesh scrambled_grid(int n, int flips, unsigned seed) {
  EditableMesh m = grid(n);
  std::mt19937 random(seed);
  int done = 0;
  for (int attempt = 0; attempt < 100 * flips && done < flips; ++attempt) {
    const auto edges = m.edges();
    const auto [a, b] = edges[random() % edges.size()];
    const auto e = m.interior_edge(a, b);
    if (e && flip_keeps_planar_shape(m, *e, 15.0)) {
      m.flip(*e);
      ++done;
    }
  }
  return m;
}

std::vector<std::array<std::uint32_t, 3>> canonical_triangles(const EditableMesh& m) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    if (!m.triangle_alive[t]) continue;
    std::array<std::uint32_t, 3> tri = m.triangles[t];
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Flips e in m when it keeps the planar triangles counter-clockwise with no angle under 10 degrees.
FlipIfValid planar_flip(EditableMesh& m) {
  return [&m](const EditableMesh::Edge& e, bool) {
    if (!flip_keeps_planar_shape(m, e, 10.0)) return false;
    m.flip(e);
    return true;
  };
}

TEST(ValenceFlips, GlideChainsGoBelowWhatGreedyFlipsReach) {
  int greedy_total = 0, glide_total = 0;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    EditableMesh greedy = scrambled_grid(16, 60, seed);
    EditableMesh glide = greedy;
    const int scrambled = valence_energy(greedy);
    flip_towards_valence_six(greedy, planar_flip(greedy), GlideLimits{.passes = 0});
    flip_towards_valence_six(glide, planar_flip(glide));
    EXPECT_LE(valence_energy(greedy), scrambled) << "seed " << seed;
    EXPECT_LE(valence_energy(glide), valence_energy(greedy)) << "seed " << seed;
    greedy_total += valence_energy(greedy);
    glide_total += valence_energy(glide);

    const TopologyReport t = analyze_topology(glide.to_mesh());
    EXPECT_TRUE(t.manifold());
    EXPECT_TRUE(t.consistently_oriented());
    EXPECT_EQ(t.euler_characteristic, 1);  // still a disk
    for (std::uint32_t f = 0; f < glide.triangles.size(); ++f) {
      const auto& tri = glide.triangles[f];
      const Vec3 n = (glide.positions[tri[1]] - glide.positions[tri[0]])
                         .cross(glide.positions[tri[2]] - glide.positions[tri[0]]);
      EXPECT_GT(n.z(), 0.0) << "folded triangle " << f;
    }
  }
  EXPECT_LT(glide_total, greedy_total);
}

TEST(ValenceFlips, ChainsThatMayBorrowGoBelowNeutralChains) {
  int neutral_total = 0, borrowing_total = 0;
  for (unsigned seed = 11; seed <= 15; ++seed) {
    EditableMesh neutral = scrambled_grid(16, 60, seed);
    // Neutral chains until they find nothing more.
    for (int round = 0; round < 20; ++round)
      if (flip_towards_valence_six(neutral, planar_flip(neutral), GlideLimits{.passes = 10}) == 0) break;
    EditableMesh borrowing = neutral;
    const int before = valence_energy(neutral);
    flip_towards_valence_six(borrowing, planar_flip(borrowing), GlideLimits{.max_debt = 2});
    EXPECT_LE(valence_energy(borrowing), before) << "seed " << seed;  // never above where it started
    neutral_total += before;
    borrowing_total += valence_energy(borrowing);
    const TopologyReport t = analyze_topology(borrowing.to_mesh());
    EXPECT_TRUE(t.manifold() && t.consistently_oriented());
    EXPECT_EQ(t.euler_characteristic, 1);
  }
  EXPECT_LT(borrowing_total, neutral_total);
}

TEST(ValenceFlips, ChainsWithoutALoweringFlipAreUndone) {
  EditableMesh m = scrambled_grid(12, 40, 7);
  // Greedy flips first, so that what is left can only be reached through neutral flips.
  flip_towards_valence_six(m, planar_flip(m), GlideLimits{.passes = 0});
  const auto before = canonical_triangles(m);
  const int energy = valence_energy(m);
  int neutral_flips = 0;
  // Neutral flips are allowed, lowering ones refused: every chain must end where it started.
  const std::size_t kept = flip_towards_valence_six(m, [&](const EditableMesh::Edge& e, bool neutral) {
    if (!neutral || !flip_keeps_planar_shape(m, e, 10.0)) return false;
    m.flip(e);
    ++neutral_flips;
    return true;
  });
  EXPECT_EQ(kept, 0u);
  EXPECT_GT(neutral_flips, 0);  // chains were tried
  EXPECT_EQ(valence_energy(m), energy);
  EXPECT_EQ(canonical_triangles(m), before);
}

/// The triangles as vertex triples in slot order: equal lists mean identical meshes (ids included).
std::vector<std::array<std::uint32_t, 3>> raw_triangles(const EditableMesh& m) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
    if (m.triangle_alive[t]) out.push_back(m.triangles[t]);
  return out;
}

TEST(ValenceFlips, CubesOfOneColourNeverShareATwoRing) {
  const EditableMesh m = scrambled_grid(64, 600, 3);
  const FlipBlocks blocks = make_flip_blocks(m, flip_block_width(m), 0.0);
  ASSERT_GT(blocks.members.size(), 8u);  // the blocked path, not one region
  std::vector<int> colour(blocks.members.size(), -1);
  for (int c = 0; c < 8; ++c)
    for (std::uint32_t cube : blocks.colours[static_cast<std::size_t>(c)]) colour[cube] = c;
  for (std::uint32_t v = 0; v < m.vertex_slots(); ++v) {
    // Every vertex within two edges of v lies in v's cube or in a cube of another colour.
    for (std::uint32_t t : m.incident[v])
      for (std::uint32_t w : m.triangles[t])
        for (std::uint32_t t2 : m.incident[w])
          for (std::uint32_t x : m.triangles[t2]) {
            const std::uint32_t a = blocks.block_of[v], b = blocks.block_of[x];
            EXPECT_TRUE(a == b || colour[a] != colour[b]) << v << " and " << x;
          }
  }
}

TEST(ValenceFlips, BlockedFlipsGiveOneResultForAnyThreadCountAndStillLowerTheEnergy) {
  for (unsigned seed = 21; seed <= 23; ++seed) {
    const EditableMesh scrambled = scrambled_grid(64, 600, seed);
    ASSERT_GT(make_flip_blocks(scrambled, flip_block_width(scrambled), 0.0).members.size(), 8u);
    std::vector<std::vector<std::array<std::uint32_t, 3>>> results;
    for (int threads : {1, 2, 4}) {
      EditableMesh m = scrambled;
      tbb::task_arena arena(threads);
      arena.execute([&] { flip_towards_valence_six(m, planar_flip(m), GlideLimits{.max_debt = 2}); });
      EXPECT_LT(valence_energy(m), valence_energy(scrambled)) << "seed " << seed;
      const TopologyReport t = analyze_topology(m.to_mesh());
      EXPECT_TRUE(t.manifold() && t.consistently_oriented());
      EXPECT_EQ(t.euler_characteristic, 1);
      results.push_back(raw_triangles(m));
    }
    EXPECT_EQ(results[0], results[1]) << "seed " << seed;
    EXPECT_EQ(results[0], results[2]) << "seed " << seed;
  }
}

TEST(ValenceFlips, EnergyChangeOfAFlipCountsTheFourVertices) {
  EditableMesh m = grid(4);
  // An interior edge of the regular grid: both ends lose one neighbour, both opposite vertices gain
  // one: 4 x (1)^2 = 4 more.
  const auto e = m.interior_edge(6, 12);
  ASSERT_TRUE(e);
  EXPECT_EQ(flip_energy_change(m, *e), 4);
  m.flip(*e);
  const auto back = m.interior_edge(e->c, e->d);
  ASSERT_TRUE(back);
  EXPECT_EQ(flip_energy_change(m, *back), -4);
}

}  // namespace
}  // namespace isopatch

namespace isopatch {
namespace {

TEST(EditLists, KeyedEdgesAreTheFilteredEdgeListInItsOrder) {
  const EditableMesh m = scrambled_grid(64, 600, 5);  // more than one block of vertices
  const KeyedEdges listed = list_keyed_edges(m, [&](std::uint32_t, std::uint32_t, double length) {
    return length < 1.2 ? std::optional<double>(-length) : std::nullopt;
  });
  std::vector<KeyedEdge> expected;
  for (const auto& [a, b] : m.edges()) {
    const double length = (m.positions[a] - m.positions[b]).norm();
    if (length < 1.2) expected.push_back({-length, {a, b}});
  }
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(listed.keyed, expected);
  EXPECT_EQ(listed.longest, m.longest_edge());
}

TEST(EditableMesh, RingDisjointClassesKeepTheirMembersMoreThanTwoEdgesApart) {
  // Boundary vertices of the grid have open fans (the full walk), inner ones closed fans.
  const EditableMesh m = scrambled_grid(24, 150, 9);
  std::vector<std::uint32_t> vertices;
  for (std::uint32_t v = 0; v < m.vertex_slots(); ++v) vertices.push_back(v);
  const auto classes = m.ring_disjoint_classes(vertices);
  std::vector<int> seen(m.vertex_slots(), 0);
  for (const auto& members : classes) {
    std::vector<char> member(m.vertex_slots(), 0);
    for (std::uint32_t v : members) member[v] = 1, ++seen[v];
    for (std::uint32_t v : members)
      for (std::uint32_t w : m.neighbours(v)) {
        EXPECT_FALSE(member[w]) << v << " and " << w << " are neighbours";
        for (std::uint32_t x : m.neighbours(w))
          EXPECT_TRUE(x == v || !member[x]) << v << " and " << x << " are two edges apart";
      }
  }
  for (std::uint32_t v = 0; v < m.vertex_slots(); ++v) EXPECT_EQ(seen[v], 1);
}

}  // namespace
}  // namespace isopatch
