// Local edits with incidence lists (see editable_mesh.hpp).
#include "remesh/editable_mesh.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <span>
#include <utility>

#include "core/spatial_order.hpp"
#include "core/vertex_role.hpp"
#include "remesh/slot_renumbering.hpp"

namespace isopatch {

EditableMesh::EditableMesh(const Mesh& mesh, std::vector<Vec3> vertex_normals)
    : positions(mesh.positions),
      normals(std::move(vertex_normals)),
      locked(mesh.positions.size(), false),
      triangles(mesh.triangles),
      triangle_alive(mesh.triangles.size(), 1),
      incident(mesh.positions.size()) {
  // Lists laid out in vertex order with the spare room a rebuilt run has.
  {
    std::vector<std::uint32_t> counts(positions.size(), 0);
    for (const Triangle& t : triangles)
      for (std::uint32_t v : t) ++counts[v];
    for (std::uint32_t v = 0; v < positions.size(); ++v)
      incident.make_room(v, counts[v] + IncidenceLists::kSpare);
  }
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (std::uint32_t v : triangles[t]) incident.push_back(v, t);
  for (const VertexAttribute& a : mesh.attributes) {
    attribute_names.push_back(a.name);
    attributes.push_back(a.values);
  }
  // A vertex is locked when one of its edges has a number of triangles other than two.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i != 2) locked[edges[i].first] = locked[edges[i].second] = true;
    i = j;
  }
}

std::optional<EditableMesh::Edge> EditableMesh::interior_edge(std::uint32_t a, std::uint32_t b) const {
  Edge e;
  e.a = a;
  e.b = b;
  int ab = 0, ba = 0;
  for (std::uint32_t t : incident[a]) {
    const Triangle& tri = triangles[t];
    const std::size_t i = corner_index(tri, a);  // a is in every triangle it is incident to
    const std::uint32_t next = tri[(i + 1) % 3], previous = tri[(i + 2) % 3];
    if (next == b) {  // holds a -> b
      e.c = previous;
      e.t_ab = t;
      ++ab;
    } else if (previous == b) {  // holds b -> a
      e.d = next;
      e.t_ba = t;
      ++ba;
    }
  }
  if (ab != 1 || ba != 1 || e.c == e.d) return std::nullopt;
  return e;
}

std::optional<EditableMesh::BoundaryEdge> EditableMesh::boundary_edge(std::uint32_t a,
                                                                      std::uint32_t b) const {
  std::optional<BoundaryEdge> found;
  for (std::uint32_t t : incident[a]) {
    const Triangle& tri = triangles[t];
    if (a == b || std::find(tri.begin(), tri.end(), b) == tri.end()) continue;
    if (found) return std::nullopt;  // a second triangle: not a boundary edge
    std::uint32_t c = tri[0];
    for (std::uint32_t v : tri)
      if (v != a && v != b) c = v;
    found = BoundaryEdge{a, b, c, t};
  }
  return found;
}

std::vector<std::uint32_t> EditableMesh::boundary_neighbours(std::uint32_t v) const {
  std::vector<std::uint32_t> list;
  for (std::uint32_t w : neighbours(v))
    if (boundary_edge(v, w)) list.push_back(w);
  return list;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> EditableMesh::edges() const {
  // Per vertex a, its larger neighbours b: sorted by (a, b) without sorting the whole list.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> list;
  list.reserve(triangles.size() * 3 / 2 + 3);  // a closed mesh has 3/2 edges per triangle
  std::vector<std::uint32_t> larger;
  for (std::uint32_t a = 0; a < positions.size(); ++a) {
    larger_neighbours(a, larger);
    for (std::uint32_t b : larger) list.emplace_back(a, b);
  }
  return list;
}

void EditableMesh::larger_neighbours(std::uint32_t a, std::vector<std::uint32_t>& out) const {
  out.clear();
  for (std::uint32_t t : incident[a])
    for (std::uint32_t b : triangles[t])
      if (b > a) out.push_back(b);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

std::vector<std::uint32_t> EditableMesh::neighbours(std::uint32_t v) const {
  std::vector<std::uint32_t> list;
  for (std::uint32_t t : incident[v])
    for (std::uint32_t w : triangles[t])
      if (w != v) list.push_back(w);
  std::sort(list.begin(), list.end());
  list.erase(std::unique(list.begin(), list.end()), list.end());
  return list;
}

std::vector<std::uint32_t> EditableMesh::common_neighbours(std::uint32_t a, std::uint32_t b) const {
  return sorted_intersection(neighbours(a), neighbours(b));
}

std::vector<std::uint32_t> sorted_intersection(const std::vector<std::uint32_t>& a,
                                               const std::vector<std::uint32_t>& b) {
  std::vector<std::uint32_t> common;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
  return common;
}

bool EditableMesh::adjacent(std::uint32_t a, std::uint32_t b) const {
  for (std::uint32_t t : incident[a]) {
    const Triangle& tri = triangles[t];
    if (std::find(tri.begin(), tri.end(), b) != tri.end()) return true;
  }
  return false;
}

namespace {

/// Greedy classes of `vertices` in list order: each takes the smallest class that none of the
/// vertices `conflicts(v, mark)` marks has taken.
template <class Conflicts>
std::vector<std::vector<std::uint32_t>> greedy_classes(std::size_t slots,
                                                       const std::vector<std::uint32_t>& vertices,
                                                       Conflicts conflicts) {
  constexpr std::uint32_t kNone = UINT32_MAX;
  std::vector<std::uint32_t> colour(slots, kNone);
  std::vector<std::vector<std::uint32_t>> classes;
  std::vector<char> taken;
  for (std::uint32_t v : vertices) {
    taken.assign(classes.size() + 1, 0);
    conflicts(v, [&](std::uint32_t w) {
      if (w != v && colour[w] != kNone) taken[colour[w]] = 1;
    });
    std::uint32_t c = 0;
    while (taken[c]) ++c;
    colour[v] = c;
    if (c == classes.size()) classes.emplace_back();
    classes[c].push_back(v);
  }
  return classes;
}

}  // namespace

std::vector<std::vector<std::uint32_t>> EditableMesh::independent_classes(
    const std::vector<std::uint32_t>& vertices) const {
  return greedy_classes(positions.size(), vertices, [&](std::uint32_t v, const auto& mark) {
    for (std::uint32_t t : incident[v])
      for (std::uint32_t w : triangles[t]) mark(w);
  });
}

std::vector<std::vector<std::uint32_t>> EditableMesh::ring_disjoint_classes(
    const std::vector<std::uint32_t>& vertices) const {
  // Within two edges of v: the vertices of the triangles of v's neighbours. When v's fan is closed
  // (each neighbour x follows v in exactly one of v's triangles and precedes it in another), those
  // neighbours are the x's alone: 6 fans of 6 triangles, 108 marks per vertex instead of the 324 of
  // walking the triangles of all three corners of every triangle of v, and no table (the sweeps run at
  // the clean-up's peak of memory). Open or odd fans take that full walk.
  constexpr std::size_t kFan = 16;
  return greedy_classes(positions.size(), vertices, [&](std::uint32_t v, const auto& mark) {
    const std::span<const std::uint32_t> fan = incident[v];
    std::array<std::uint32_t, kFan> after{}, before{};
    bool closed = fan.size() <= kFan;
    for (std::size_t k = 0; closed && k < fan.size(); ++k) {
      const Triangle& tri = triangles[fan[k]];
      const std::size_t i = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
      after[k] = tri[(i + 1) % 3];
      before[k] = tri[(i + 2) % 3];
    }
    if (closed) {
      std::sort(after.begin(), after.begin() + static_cast<std::ptrdiff_t>(fan.size()));
      std::sort(before.begin(), before.begin() + static_cast<std::ptrdiff_t>(fan.size()));
      closed =
          std::equal(after.begin(), after.begin() + static_cast<std::ptrdiff_t>(fan.size()), before.begin());
    }
    if (closed) {
      for (std::size_t k = 0; k < fan.size(); ++k)
        for (std::uint32_t t : incident[after[k]])
          for (std::uint32_t x : triangles[t]) mark(x);
      return;
    }
    for (std::uint32_t t : fan)
      for (std::uint32_t w : triangles[t])
        for (std::uint32_t t2 : incident[w])
          for (std::uint32_t x : triangles[t2]) mark(x);
  });
}

void EditableMesh::replace_vertex(std::uint32_t t, std::uint32_t from, std::uint32_t to) {
  for (std::uint32_t& v : triangles[t])
    if (v == from) v = to;
}

void EditableMesh::detach(std::uint32_t v, std::uint32_t t) {
  incident.remove(v, t);
}

void EditableMesh::set_triangle(std::uint32_t id, const Triangle& t) {
  triangles[id] = t;
  triangle_alive[id] = 1;
  for (std::uint32_t v : t) incident.push_back(v, id);
}

std::pair<std::uint32_t, std::uint32_t> EditableMesh::add_split_slots(std::size_t splits) {
  const auto first_vertex = static_cast<std::uint32_t>(positions.size());
  const auto first_triangle = static_cast<std::uint32_t>(triangles.size());
  const std::size_t vertices = positions.size() + splits;
  positions.resize(vertices, Vec3::Zero());
  normals.resize(vertices, Vec3::UnitZ());
  locked.resize(vertices, false);
  incident.reserve(splits);
  for (std::size_t k = 0; k < splits; ++k) incident.add_vertex();
  for (std::vector<float>& values : attributes) values.resize(vertices, 0.0f);
  triangles.resize(triangles.size() + 2 * splits, Triangle{0, 0, 0});
  triangle_alive.resize(triangles.size(), 0);
  return {first_vertex, first_triangle};
}

void EditableMesh::split(const Edge& e, const Vec3& p, const Vec3& n, std::uint32_t m, std::uint32_t t) {
  positions[m] = p;
  normals[m] = n;
  incident.make_room(m, 8);  // four triangles now, about six once the clean-up is done with it
  for (std::size_t k = 0; k < attributes.size(); ++k)
    attributes[k][m] = attribute_names[k] == "role" ? role_value(VertexRole::Remeshed) : attributes[k][e.a];
  // (a, b, c) -> (a, m, c) + (m, b, c); (b, a, d) -> (b, m, d) + (m, a, d).
  replace_vertex(e.t_ab, e.b, m);
  detach(e.b, e.t_ab);
  incident.push_back(m, e.t_ab);
  set_triangle(t, {m, e.b, e.c});
  replace_vertex(e.t_ba, e.a, m);
  detach(e.a, e.t_ba);
  incident.push_back(m, e.t_ba);
  set_triangle(t + 1, {m, e.a, e.d});
}

double EditableMesh::longest_edge() const {
  double longest = 0.0;
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    if (!triangle_alive[t]) continue;
    const Triangle& tri = triangles[t];
    for (std::size_t k = 0; k < 3; ++k)
      longest = std::max(longest, (positions[tri[k]] - positions[tri[(k + 1) % 3]]).squaredNorm());
  }
  return std::sqrt(longest);
}

std::uint32_t EditableMesh::split(const Edge& e, const Vec3& p, const Vec3& n) {
  const auto [m, t] = add_split_slots(1);
  split(e, p, n, m, t);
  return m;
}

std::uint32_t EditableMesh::split_boundary(const BoundaryEdge& e, const Vec3& p, const Vec3& n) {
  const auto [m, t] = add_split_slots(1);
  positions[m] = p;
  normals[m] = n;
  locked[m] = true;
  for (std::size_t k = 0; k < attributes.size(); ++k)
    attributes[k][m] = attribute_names[k] == "role" ? role_value(VertexRole::Remeshed) : attributes[k][e.a];
  // (.., a, .., b, ..) -> the same with b replaced by m, and a new one with a replaced by m: both keep
  // the triangle's orientation, and the boundary runs a - m - b.
  Triangle second = triangles[e.t];
  second[corner_index(second, e.a)] = m;
  replace_vertex(e.t, e.b, m);
  detach(e.b, e.t);
  incident.push_back(m, e.t);
  set_triangle(t, second);
  return m;
}

void EditableMesh::collapse(const Edge& e, const Vec3& p, const Vec3& n) {
  for (std::uint32_t t : {e.t_ab, e.t_ba}) {
    triangle_alive[t] = 0;
    for (std::uint32_t v : triangles[t]) detach(v, t);
  }
  for (std::uint32_t t : incident[e.a]) replace_vertex(t, e.a, e.b);
  incident.move_all(e.a, e.b);
  positions[e.b] = p;
  normals[e.b] = n;
}

void EditableMesh::collapse_boundary(const BoundaryEdge& e) {
  triangle_alive[e.t] = 0;
  for (std::uint32_t v : triangles[e.t]) detach(v, e.t);
  for (std::uint32_t t : incident[e.a]) replace_vertex(t, e.a, e.b);
  incident.move_all(e.a, e.b);
}

void EditableMesh::flip(const Edge& e) {
  // (a, b, c) + (b, a, d) -> (a, d, c) + (b, c, d).
  triangles[e.t_ab] = {e.a, e.d, e.c};
  triangles[e.t_ba] = {e.b, e.c, e.d};
  detach(e.b, e.t_ab);
  detach(e.a, e.t_ba);
  incident.push_back(e.d, e.t_ab);
  incident.push_back(e.c, e.t_ba);
}

std::vector<std::uint32_t> EditableMesh::compact() {
  std::vector<std::uint32_t> order;
  for (std::uint32_t v = 0; v < positions.size(); ++v)
    if (alive(v)) order.push_back(v);
  return renumber(order, false);
}

std::vector<std::uint32_t> EditableMesh::compact_in_space_order() {
  std::vector<bool> live(positions.size());
  for (std::uint32_t v = 0; v < positions.size(); ++v) live[v] = alive(v);
  return renumber(z_order(positions, live), true);
}

std::vector<std::uint32_t> EditableMesh::renumber(const std::vector<std::uint32_t>& order, bool space_order) {
  std::vector<std::uint32_t> vertex_id(positions.size(), kDeadSlot);
  for (std::uint32_t k = 0; k < order.size(); ++k) vertex_id[order[k]] = k;
  // The live triangles in their order, or (in space order) by their smallest new corner id with ties
  // in their order (a counting sort: stable, linear).
  std::vector<std::uint32_t> triangle_id(triangles.size(), kDeadSlot);
  if (space_order) {
    const auto smallest = [&](const Triangle& t) {
      return std::min({vertex_id[t[0]], vertex_id[t[1]], vertex_id[t[2]]});
    };
    std::vector<std::uint32_t> first(order.size() + 1, 0);
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
      if (triangle_alive[t]) ++first[smallest(triangles[t]) + 1];
    for (std::size_t k = 1; k < first.size(); ++k) first[k] += first[k - 1];
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
      if (triangle_alive[t]) triangle_id[t] = first[smallest(triangles[t])]++;
  } else {
    std::uint32_t kept = 0;
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
      if (triangle_alive[t]) triangle_id[t] = kept++;
  }
  renumber_slots(triangles, triangle_id, Triangle{});
  for (Triangle& tri : triangles)
    for (std::uint32_t& v : tri) v = vertex_id[v];
  triangle_alive.assign(triangles.size(), 1);
  triangle_alive.shrink_to_fit();
  // Kept order: the runs squeezed in place (no second copy while the clean-up is at its largest);
  // space order: laid out afresh in the new order, so that near vertices' lists are near too.
  if (space_order)
    incident.rebuild(order, triangle_id);
  else
    incident.renumber_in_order(vertex_id, order.size(), triangle_id);
  renumber_slots(positions, vertex_id, Vec3::Zero().eval());
  renumber_slots(normals, vertex_id, Vec3::Zero().eval());
  renumber_slots(locked, vertex_id, false);
  for (std::vector<float>& values : attributes) renumber_slots(values, vertex_id, 0.0f);
  return vertex_id;
}

Mesh EditableMesh::to_mesh() const {
  Mesh mesh;
  std::vector<std::uint32_t> index(positions.size(), UINT32_MAX);
  for (std::uint32_t v = 0; v < positions.size(); ++v) {
    if (!alive(v)) continue;
    index[v] = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.push_back(positions[v]);
  }
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    if (triangle_alive[t])
      mesh.triangles.push_back({index[triangles[t][0]], index[triangles[t][1]], index[triangles[t][2]]});
  for (std::size_t k = 0; k < attributes.size(); ++k) {
    std::vector<float> values;
    values.reserve(mesh.positions.size());
    for (std::uint32_t v = 0; v < positions.size(); ++v)
      if (alive(v)) values.push_back(attributes[k][v]);
    mesh.set_attribute(attribute_names[k], std::move(values));
  }
  return mesh;
}

}  // namespace isopatch
