// IncidenceLists against a plain list per vertex under random edits (growth, moves between runs,
// new blocks, rebuilds), the in-place renumbering of per-slot arrays, the Z-order of points, and the
// space-order compaction of EditableMesh.
#include <isopatch/error.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <tbb/parallel_for.h>

#include "core/spatial_order.hpp"
#include "remesh/editable_mesh.hpp"
#include "remesh/incidence_lists.hpp"
#include "remesh/slot_renumbering.hpp"

namespace isopatch {
namespace {

void expect_same(const IncidenceLists& lists, const std::vector<std::vector<std::uint32_t>>& model) {
  ASSERT_EQ(lists.size(), model.size());
  for (std::uint32_t v = 0; v < model.size(); ++v) {
    const auto list = lists[v];
    ASSERT_EQ(std::vector<std::uint32_t>(list.begin(), list.end()), model[v]) << "vertex " << v;
    EXPECT_EQ(lists.empty(v), model[v].empty());
  }
}

TEST(IncidenceLists, MatchAListPerVertexUnderRandomEditsAcrossBlocks) {
  std::mt19937 random(7);
  IncidenceLists lists(50);
  std::vector<std::vector<std::uint32_t>> model(50);
  // Enough entries for several blocks, lists long enough to move many times.
  for (int step = 0; step < 400000; ++step) {
    const int op = static_cast<int>(random() % 10);
    const auto v = static_cast<std::uint32_t>(random() % model.size());
    if (op < 6 && model[v].size() < 3000) {  // lists stay under the 16-bit count
      const auto t = static_cast<std::uint32_t>(random() % 1000);
      lists.push_back(v, t);
      model[v].push_back(t);
    } else if (op < 8 && !model[v].empty()) {
      const std::uint32_t t = model[v][random() % model[v].size()];
      lists.remove(v, t);
      model[v].erase(std::find(model[v].begin(), model[v].end(), t));
    } else if (op == 8 && random() % 50 == 0) {
      const auto w = static_cast<std::uint32_t>(random() % model.size());
      if (w == v) continue;
      lists.move_all(v, w);
      model[w].insert(model[w].end(), model[v].begin(), model[v].end());
      model[v].clear();
    } else if (random() % 200 == 0) {
      EXPECT_EQ(lists.add_vertex(), model.size());
      model.emplace_back();
    }
  }
  expect_same(lists, model);
  const IncidenceLists copy = lists;
  expect_same(copy, model);
  // Rebuilt in reverse order with ids renamed.
  std::vector<std::uint32_t> order, rename(1000);
  for (std::uint32_t v = 0; v < model.size(); ++v)
    order.push_back(static_cast<std::uint32_t>(model.size()) - 1 - v);
  for (std::uint32_t t = 0; t < rename.size(); ++t) rename[t] = 5000 + t;
  lists.rebuild(order, rename);
  std::vector<std::vector<std::uint32_t>> expected;
  for (std::uint32_t old : order) {
    expected.emplace_back();
    for (std::uint32_t t : model[old]) expected.back().push_back(rename[t]);
  }
  expect_same(lists, expected);
  lists.push_back(0, 1);  // still editable after the rebuild
  expected[0].push_back(1);
  expect_same(lists, expected);
}

TEST(IncidenceLists, DifferentVerticesChangeInParallel) {
  constexpr std::uint32_t kVertices = 4000;
  IncidenceLists lists(kVertices);
  tbb::parallel_for(std::uint32_t{0}, kVertices, [&](std::uint32_t v) {
    for (std::uint32_t k = 0; k < 40 + v % 50; ++k) lists.push_back(v, v * 1000 + k);
    lists.remove(v, v * 1000);
  });
  for (std::uint32_t v = 0; v < kVertices; ++v) {
    const auto list = lists[v];
    ASSERT_EQ(list.size(), 39 + v % 50);
    for (std::size_t k = 0; k < list.size(); ++k) EXPECT_EQ(list[k], v * 1000 + k + 1);
  }
}

TEST(IncidenceLists, RefusesMoreThan65535EntriesAtOneVertex) {
  IncidenceLists lists(1);
  for (std::uint32_t t = 0; t < 65535; ++t) lists.push_back(0, t);
  EXPECT_THROW(lists.push_back(0, 1), InputError);
  EXPECT_EQ(lists[0].size(), 65535u);
}

TEST(SlotRenumbering, MovesEveryKeptValueToItsNewSlotInPlace) {
  // A random renumbering with dropped slots, against a gather into a new array.
  std::mt19937 random(11);
  for (int round = 0; round < 50; ++round) {
    const std::size_t slots = 1 + random() % 200;
    std::vector<std::uint32_t> kept_slots;
    for (std::uint32_t s = 0; s < slots; ++s)
      if (random() % 4 != 0) kept_slots.push_back(s);
    std::vector<std::uint32_t> new_ids(kept_slots.size());
    for (std::uint32_t k = 0; k < new_ids.size(); ++k) new_ids[k] = k;
    if (round % 2 == 1) std::shuffle(new_ids.begin(), new_ids.end(), random);  // even rounds keep the order
    std::vector<std::uint32_t> new_id(slots, kDroppedSlot);
    for (std::size_t k = 0; k < kept_slots.size(); ++k) new_id[kept_slots[k]] = new_ids[k];
    // Values for the first slots only: the rest take the fill.
    const std::size_t filled = slots - random() % (slots / 2 + 1);
    std::vector<int> values(filled);
    std::vector<bool> bits(filled);
    for (std::size_t s = 0; s < filled; ++s) values[s] = static_cast<int>(s) * 10, bits[s] = s % 3 == 0;
    std::vector<int> expected(kept_slots.size());
    std::vector<bool> expected_bits(kept_slots.size());
    for (std::uint32_t s = 0; s < slots; ++s)
      if (new_id[s] != kDroppedSlot) {
        expected[new_id[s]] = s < filled ? values[s] : -1;
        expected_bits[new_id[s]] = s < filled ? bool(bits[s]) : true;
      }
    renumber_slots(values, new_id, -1);
    renumber_slots(bits, new_id, true);
    EXPECT_EQ(values, expected);
    EXPECT_EQ(bits, expected_bits);
  }
  std::vector<double> never_filled;  // a cache that was never filled stays empty
  renumber_slots(never_filled, {0, kDroppedSlot, 1}, 1.0);
  EXPECT_TRUE(never_filled.empty());
}

TEST(ZOrder, KeyInterleavesBitsAndOrderFollowsTheCurve) {
  EXPECT_EQ(z_order_key(1, 0, 0), 1u);
  EXPECT_EQ(z_order_key(0, 1, 0), 2u);
  EXPECT_EQ(z_order_key(0, 0, 1), 4u);
  EXPECT_EQ(z_order_key(2, 0, 0), 8u);
  EXPECT_EQ(z_order_key(0x1fffff, 0x1fffff, 0x1fffff), (std::uint64_t{1} << 63) - 1);
  // The eight corners of a cube come out in the curve's order; a dropped point is left out.
  std::vector<Vec3> points;
  for (int i = 7; i >= 0; --i) points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  points.emplace_back(0.5, 0.5, 0.5);
  std::vector<bool> keep(points.size(), true);
  keep.back() = false;
  EXPECT_EQ(z_order(points, keep), (std::vector<std::uint32_t>{7, 6, 5, 4, 3, 2, 1, 0}));
  EXPECT_EQ(z_order(points, {}).size(), points.size());
}

/// A sphere of latitude-longitude quads split into triangles, numbered ring by ring.
Mesh uv_sphere(int rings, int sectors) {
  Mesh m;
  m.positions.push_back({0, 0, 1});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      const double theta = M_PI * i / rings, phi = 2 * M_PI * j / sectors;
      m.positions.push_back(
          {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
    }
  m.positions.push_back({0, 0, -1});
  const auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>(1 + (i - 1) * sectors + (j % sectors));
  };
  const auto south = static_cast<std::uint32_t>(m.positions.size() - 1);
  for (int j = 0; j < sectors; ++j) m.triangles.push_back({0, at(1, j), at(1, j + 1)});
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  for (int j = 0; j < sectors; ++j) m.triangles.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
  return m;
}

TEST(EditableMesh, CompactInSpaceOrderKeepsTheMeshUpToTheNumbering) {
  // Numbered at random, as after many splits appended their vertices.
  const Mesh sphere = [] {
    const Mesh ordered = uv_sphere(24, 32);
    std::vector<std::uint32_t> shuffle(ordered.positions.size());
    for (std::uint32_t v = 0; v < shuffle.size(); ++v) shuffle[v] = v;
    std::shuffle(shuffle.begin(), shuffle.end(), std::mt19937(3));
    Mesh m = ordered;
    for (std::uint32_t v = 0; v < shuffle.size(); ++v) m.positions[shuffle[v]] = ordered.positions[v];
    for (Triangle& t : m.triangles)
      for (std::uint32_t& v : t) v = shuffle[v];
    return m;
  }();
  ASSERT_TRUE(analyze_topology(sphere).watertight());
  std::vector<Vec3> normals;
  for (const Vec3& p : sphere.positions) normals.push_back(p.normalized());
  EditableMesh m(sphere, normals);
  m.attribute_names.push_back("id");
  m.attributes.emplace_back();
  for (std::size_t v = 0; v < sphere.positions.size(); ++v) m.attributes[0].push_back(static_cast<float>(v));
  // Dead slots: split some edges, then collapse one new vertex away.
  const Triangle first = m.triangles[0], other = m.triangles[300];
  const auto edge = [&](std::uint32_t u, std::uint32_t w) {
    const auto e = m.interior_edge(u, w);
    EXPECT_TRUE(e);
    return *e;
  };
  const Vec3 mid = 0.5 * (m.positions[first[0]] + m.positions[first[1]]);
  const std::uint32_t a = m.split(edge(first[0], first[1]), mid, mid.normalized());
  const Vec3 mid2 = 0.5 * (m.positions[other[0]] + m.positions[other[1]]);
  m.split(edge(other[0], other[1]), mid2, mid2.normalized());
  m.collapse(edge(a, first[0]), m.positions[first[0]], m.normals[first[0]]);
  const Mesh before = m.to_mesh();
  const std::vector<std::uint32_t> new_id = m.compact_in_space_order();
  EXPECT_EQ(new_id[a], EditableMesh::kDeadSlot);
  const Mesh after = m.to_mesh();
  ASSERT_EQ(after.vertex_count(), before.vertex_count());
  ASSERT_EQ(after.triangle_count(), before.triangle_count());
  // The same triangles (as position triples, rotated to start at the smallest) and attributes.
  const auto corners = [](const Mesh& mesh) {
    std::vector<std::array<std::array<double, 3>, 3>> list;
    for (const Triangle& t : mesh.triangles) {
      std::array<std::array<double, 3>, 3> c;
      for (std::size_t k = 0; k < 3; ++k)
        c[k] = {mesh.positions[t[k]].x(), mesh.positions[t[k]].y(), mesh.positions[t[k]].z()};
      std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
      list.push_back(c);
    }
    std::sort(list.begin(), list.end());
    return list;
  };
  EXPECT_EQ(corners(after), corners(before));
  // Each attribute value stays with its vertex's position.
  const auto tagged = [](const Mesh& mesh) {
    std::vector<std::array<double, 4>> list;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      list.push_back({mesh.positions[v].x(), mesh.positions[v].y(), mesh.positions[v].z(),
                      static_cast<double>(mesh.attributes[0].values[v])});
    std::sort(list.begin(), list.end());
    return list;
  };
  EXPECT_EQ(tagged(after), tagged(before));
  for (std::uint32_t v = 0; v < m.vertex_slots(); ++v)
    for (std::uint32_t t : m.incident[v]) {
      EXPECT_NE(std::find(m.triangles[t].begin(), m.triangles[t].end(), v), m.triangles[t].end());
    }
  // Neighbours are far nearer in the numbering than at random.
  const auto mean_gap = [](const Mesh& mesh) {
    double sum = 0.0;
    for (const Triangle& t : mesh.triangles)
      for (std::size_t k = 0; k < 3; ++k) sum += std::abs(double(t[k]) - double(t[(k + 1) % 3]));
    return sum / (3.0 * static_cast<double>(mesh.triangles.size()));
  };
  EXPECT_LT(mean_gap(after), 0.25 * mean_gap(before));
  // Triangles in the order of their smallest vertex.
  for (std::size_t t = 1; t < after.triangles.size(); ++t)
    EXPECT_LE(*std::min_element(after.triangles[t - 1].begin(), after.triangles[t - 1].end()),
              *std::min_element(after.triangles[t].begin(), after.triangles[t].end()));
  const TopologyReport topology = analyze_topology(after);
  EXPECT_TRUE(topology.watertight() && topology.manifold() && topology.consistently_oriented());
}

}  // namespace
}  // namespace isopatch
