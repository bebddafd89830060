// Local edits of EditableMesh on an octahedron: every edit keeps the mesh closed, manifold and
// consistently oriented, with the Euler characteristic of a sphere.
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>

#include "remesh/editable_mesh.hpp"

namespace isopatch {
namespace {

Mesh octahedron() {
  Mesh m;
  m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

EditableMesh editable(const Mesh& m) {
  std::vector<Vec3> normals;
  for (const Vec3& p : m.positions) normals.push_back(p.normalized());
  return EditableMesh(m, normals);
}

void expect_closed_sphere(const Mesh& m) {
  const TopologyReport t = analyze_topology(m);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.unreferenced_vertices, 0u);
}

TEST(EditableMesh, FindsInteriorEdgesWithTheirOppositeVertices) {
  const EditableMesh m = editable(octahedron());
  const auto e = m.interior_edge(0, 2);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->c, 4u);                  // (0, 2, 4) holds 0 -> 2
  EXPECT_EQ(e->d, 5u);                  // (2, 0, 5) holds 2 -> 0
  EXPECT_FALSE(m.interior_edge(0, 1));  // opposite vertices share no edge
  EXPECT_EQ(m.valence(0), 4u);
  EXPECT_EQ(m.edges().size(), 12u);
  for (std::uint32_t v = 0; v < 6; ++v) EXPECT_FALSE(m.locked[v]);
}

TEST(EditableMesh, SplitAddsOneVertexAndTwoTriangles) {
  EditableMesh m = editable(octahedron());
  const auto e = m.interior_edge(0, 2);
  ASSERT_TRUE(e);
  const std::uint32_t v = m.split(*e, Vec3(0.5, 0.5, 0), Vec3(1, 1, 0).normalized());
  EXPECT_EQ(v, 6u);
  EXPECT_EQ(m.valence(v), 4u);
  EXPECT_FALSE(m.adjacent(0, 2));
  const Mesh out = m.to_mesh();
  EXPECT_EQ(out.vertex_count(), 7u);
  EXPECT_EQ(out.triangle_count(), 10u);
  expect_closed_sphere(out);
}

TEST(EditableMesh, FlipReplacesTheEdgeByTheOtherDiagonal) {
  EditableMesh m = editable(octahedron());
  // Split first so that the flip does not create a duplicate edge, then flip an edge at the new vertex.
  const std::uint32_t v = m.split(*m.interior_edge(0, 2), Vec3(0.5, 0.5, 0), Vec3(1, 1, 0).normalized());
  const auto e = m.interior_edge(4, 0);
  ASSERT_TRUE(e);
  ASSERT_FALSE(m.adjacent(e->c, e->d));
  m.flip(*e);
  EXPECT_FALSE(m.adjacent(4, 0));
  EXPECT_TRUE(m.adjacent(e->c, e->d));
  EXPECT_TRUE(m.alive(v));
  expect_closed_sphere(m.to_mesh());
}

TEST(EditableMesh, CollapseRemovesOneVertexAndTwoTriangles) {
  EditableMesh m = editable(octahedron());
  const std::uint32_t v = m.split(*m.interior_edge(0, 2), Vec3(0.5, 0.5, 0), Vec3(1, 1, 0).normalized());
  const auto e = m.interior_edge(v, 0);
  ASSERT_TRUE(e);
  m.collapse(*e, Vec3(1, 0, 0), Vec3(1, 0, 0));
  EXPECT_FALSE(m.alive(v));
  const Mesh out = m.to_mesh();
  EXPECT_EQ(out.vertex_count(), 6u);
  EXPECT_EQ(out.triangle_count(), 8u);
  expect_closed_sphere(out);
}

TEST(EditableMesh, CompactDropsDeadSlotsAndKeepsTheMeshAndItsOrder) {
  EditableMesh m = editable(octahedron());
  m.attribute_names.push_back("id");
  m.attributes.push_back({0, 1, 2, 3, 4, 5});
  // Split two edges, then collapse one of the new vertices away: dead vertex and triangle slots.
  const std::uint32_t a = m.split(*m.interior_edge(0, 2), Vec3(0.7, 0.7, 0), Vec3(0.7, 0.7, 0).normalized());
  m.split(*m.interior_edge(1, 3), Vec3(-0.7, -0.7, 0), Vec3(-0.7, -0.7, 0).normalized());
  m.collapse(*m.interior_edge(a, 0), Vec3(1, 0, 0), Vec3(1, 0, 0));
  const Mesh before = m.to_mesh();
  const std::size_t slots = m.vertex_slots(), triangle_slots = m.triangles.size();
  const std::vector<std::uint32_t> new_id = m.compact();
  ASSERT_EQ(new_id.size(), slots);
  EXPECT_EQ(new_id[a], EditableMesh::kDeadSlot);
  EXPECT_LT(m.vertex_slots(), slots);
  EXPECT_LT(m.triangles.size(), triangle_slots);
  std::uint32_t next = 0;  // live slots keep their order
  for (std::uint32_t v = 0; v < slots; ++v)
    if (new_id[v] != EditableMesh::kDeadSlot) {
      EXPECT_EQ(new_id[v], next++);
    }
  EXPECT_EQ(next, m.vertex_slots());
  const Mesh after = m.to_mesh();
  EXPECT_EQ(after.positions, before.positions);
  EXPECT_EQ(after.triangles, before.triangles);
  ASSERT_EQ(after.attributes.size(), 1u);
  EXPECT_EQ(after.attributes[0].values, before.attributes[0].values);
  for (std::uint32_t v = 0; v < m.vertex_slots(); ++v)  // the incidence follows the new ids
    for (std::uint32_t t : m.incident[v]) {
      ASSERT_LT(t, m.triangles.size());
      EXPECT_NE(std::find(m.triangles[t].begin(), m.triangles[t].end(), v), m.triangles[t].end());
    }
  expect_closed_sphere(after);
}

TEST(EditableMesh, BoundaryVerticesAreLockedAndAttributesFollow) {
  Mesh m = octahedron();
  m.triangles.pop_back();  // opens the mesh: 0, 3 and 5 are on the boundary
  m.set_attribute("role", std::vector<float>(6, 2.0f));
  EditableMesh e = editable(m);
  EXPECT_TRUE(e.locked[0] && e.locked[3] && e.locked[5]);
  EXPECT_FALSE(e.locked[1] || e.locked[2] || e.locked[4]);
  EXPECT_FALSE(e.interior_edge(0, 3));  // a boundary edge has one triangle
  const std::uint32_t v = e.split(*e.interior_edge(1, 2), Vec3(-0.5, 0.5, 0), Vec3(-1, 1, 0).normalized());
  const Mesh out = e.to_mesh();
  ASSERT_NE(out.find_attribute("role"), nullptr);
  EXPECT_EQ((*out.find_attribute("role"))[v], 5.0f);
  EXPECT_EQ((*out.find_attribute("role"))[0], 2.0f);
}

TEST(EditableMesh, BoundaryCollapseMergesAlongTheCut) {
  // A 3 x 3 grid of squares in the plane, cut by diagonals (i, j) - (i+1, j+1); vertex (i, j) = 4 j + i.
  Mesh m;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) m.positions.push_back({double(i), double(j), 0.0});
  for (std::uint32_t j = 0; j < 3; ++j)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t p = 4 * j + i;
      m.triangles.push_back({p, p + 1, p + 5});
      m.triangles.push_back({p, p + 5, p + 4});
    }
  EditableMesh e(m, std::vector<Vec3>(16, Vec3(0, 0, 1)));
  EXPECT_FALSE(e.boundary_edge(1, 5));  // interior edge: two triangles
  EXPECT_FALSE(e.boundary_edge(0, 6));  // no edge at all
  const auto edge = e.boundary_edge(1, 0);
  ASSERT_TRUE(edge);
  EXPECT_EQ(edge->c, 5u);
  std::vector<std::uint32_t> ends = e.boundary_neighbours(1);
  EXPECT_EQ(ends, (std::vector<std::uint32_t>{0, 2}));
  e.collapse_boundary(*edge);
  EXPECT_FALSE(e.alive(1));
  EXPECT_EQ(e.positions[0], Vec3(0, 0, 0));  // the kept end does not move
  EXPECT_EQ(e.boundary_neighbours(0), (std::vector<std::uint32_t>{2, 4}));
  const Mesh out = e.to_mesh();
  EXPECT_EQ(out.vertex_count(), 15u);
  EXPECT_EQ(out.triangle_count(), 17u);
  const TopologyReport t = analyze_topology(out);
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_EQ(t.euler_characteristic, 1);
}

}  // namespace
}  // namespace isopatch
