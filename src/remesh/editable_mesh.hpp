#pragma once
// A triangle mesh that supports local edits (edge split, collapse and flip) with vertex-to-triangle
// incidence kept up to date. Removed triangles and vertices are marked dead and dropped by to_mesh().
// The surface normals (unit gradients) are stored per vertex for the validity checks of the remesher.

#include <isopatch/mesh.hpp>

#include "remesh/incidence_lists.hpp"
#include "remesh/slot_renumbering.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace isopatch {

class EditableMesh {
 public:
  /// Copies `mesh` and builds the incidence. \pre `mesh` is valid; `normals` has one unit vector per
  /// vertex (the surface normal there).
  EditableMesh(const Mesh& mesh, std::vector<Vec3> normals);

  /// An interior edge a -> b: the triangle holding the directed edge a -> b with its third vertex c,
  /// and the triangle holding b -> a with its third vertex d.
  struct Edge {
    std::uint32_t a = 0, b = 0, c = 0, d = 0;
    std::uint32_t t_ab = 0, t_ba = 0;
  };
  /// The edge between a and b when it has exactly two triangles, consistently oriented.
  std::optional<Edge> interior_edge(std::uint32_t a, std::uint32_t b) const;
  /// A boundary edge a - b: the one triangle t that holds it, and its third vertex c.
  struct BoundaryEdge {
    std::uint32_t a = 0, b = 0, c = 0, t = 0;
  };
  /// The edge between a and b when exactly one live triangle holds it.
  std::optional<BoundaryEdge> boundary_edge(std::uint32_t a, std::uint32_t b) const;
  /// The neighbours w of v whose edge v - w is a boundary edge (two on a manifold boundary curve).
  std::vector<std::uint32_t> boundary_neighbours(std::uint32_t v) const;
  /// Every undirected edge between live vertices, once, as (smaller, larger).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges() const;
  /// The neighbours b > a of a, ascending, each once, into `out` (cleared first): edges() in pieces.
  void larger_neighbours(std::uint32_t a, std::vector<std::uint32_t>& out) const;
  /// Vertices adjacent to both a and b, sorted (the link condition of a collapse counts them).
  std::vector<std::uint32_t> common_neighbours(std::uint32_t a, std::uint32_t b) const;
  /// Distinct neighbours of v.
  std::vector<std::uint32_t> neighbours(std::uint32_t v) const;
  /// Neighbours of v, counted from its triangles: one more than their number on the boundary (one fan).
  std::size_t valence(std::uint32_t v) const { return incident[v].size() + (locked[v] ? 1 : 0); }
  bool adjacent(std::uint32_t a, std::uint32_t b) const;
  /// `vertices` split into classes of which no two members are adjacent, greedily in list order (each
  /// takes the smallest class no earlier neighbour took): the same classes for the same mesh and list,
  /// so the members of a class can move in parallel with one result.
  std::vector<std::vector<std::uint32_t>> independent_classes(
      const std::vector<std::uint32_t>& vertices) const;
  /// The same with no two members of a class within two edges of each other (their rings of
  /// neighbours are disjoint): members of a class may each rewrite data of their whole ring.
  std::vector<std::vector<std::uint32_t>> ring_disjoint_classes(
      const std::vector<std::uint32_t>& vertices) const;

  /// Slots for `splits` splits at the end: that many dead vertex slots (not locked, attributes 0,
  /// empty incidence) and twice that many dead triangle slots. Returns the first new vertex slot and
  /// the first new triangle slot; split k of them (0 <= k < splits) uses vertex first_vertex + k and
  /// triangles first_triangle + 2k, + 2k + 1 (split()). Slots no split used stay dead until compact().
  std::pair<std::uint32_t, std::uint32_t> add_split_slots(std::size_t splits);
  /// Splits the edge at vertex slot m (position p, normal n), adding triangles t and t + 1; the slots
  /// come from add_split_slots and are unused. Attributes are copied from e.a. Writes only m, t, t + 1,
  /// the two triangles of e and the lists of a, b, c, d and m, so splits of far-apart edges may run at
  /// once.
  void split(const Edge& e, const Vec3& p, const Vec3& n, std::uint32_t m, std::uint32_t t);
  /// One split into new slots of its own (add_split_slots(1)); returns the new vertex.
  std::uint32_t split(const Edge& e, const Vec3& p, const Vec3& n);
  /// Splits the boundary edge e at a new vertex (position p, normal n, locked: it lies on the boundary)
  /// in slots of its own: e.t becomes two triangles with its orientation, one triangle slot is added
  /// (the second of add_split_slots(1) stays dead). Attributes are copied from e.a. Returns the new vertex.
  std::uint32_t split_boundary(const BoundaryEdge& e, const Vec3& p, const Vec3& n);
  /// Removes e.a, merging it into e.b, which moves to (p, n). \pre the link condition holds.
  void collapse(const Edge& e, const Vec3& p, const Vec3& n);
  /// Removes e.a, merging it into e.b along their boundary edge: triangle e.t disappears and e.a's other
  /// triangles take e.b, which keeps its position. \pre the link condition holds (e.a and e.b share
  /// only the neighbour e.c) and e.a has another triangle than e.t.
  void collapse_boundary(const BoundaryEdge& e);
  /// Replaces a-b by c-d.
  void flip(const Edge& e);

  /// Drops the dead vertex and triangle slots, renumbering the live ones in their order (so to_mesh()
  /// and every order-driven pass see the same mesh as before), keeps each incidence list's order, and
  /// releases the spare capacity. Returns the new id of every old vertex slot (kDeadSlot for a dead
  /// one), for the per-vertex data that callers hold.
  std::vector<std::uint32_t> compact();
  /// The same, but the live vertices are renumbered along the Z-order curve of their positions
  /// (spatial_order.hpp) and the triangles by their smallest new vertex id (ties in their old order),
  /// so that neighbours in the mesh sit mostly near each other in memory; every incidence list is
  /// rebuilt (in its old order) in one sweep, so the lists of near vertices are near each other too.
  /// The mesh is the same up to the numbering; deterministic.
  std::vector<std::uint32_t> compact_in_space_order();
  static constexpr std::uint32_t kDeadSlot = kDroppedSlot;

  std::size_t vertex_slots() const { return positions.size(); }
  /// The length of the longest edge of a live triangle (0 without one).
  double longest_edge() const;
  bool alive(std::uint32_t v) const { return !incident.empty(v); }
  /// The mesh of live triangles and referenced vertices, attributes carried along.
  Mesh to_mesh() const;

  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<bool> locked;  ///< on a boundary edge at construction: never moved or removed
  std::vector<Triangle> triangles;
  /// Per triangle slot: 1 while live. Bytes, not bits: collapses in far-apart regions clear entries
  /// concurrently (block_edits.hpp).
  std::vector<std::uint8_t> triangle_alive;
  IncidenceLists incident;                     ///< live triangles per vertex
  std::vector<std::vector<float>> attributes;  ///< per attribute, per vertex slot
  std::vector<std::string> attribute_names;

 private:
  void replace_vertex(std::uint32_t t, std::uint32_t from, std::uint32_t to);
  void detach(std::uint32_t v, std::uint32_t t);
  /// Triangle slot id becomes t, live, in the lists of its vertices.
  void set_triangle(std::uint32_t id, const Triangle& t);
  /// compact() with the live vertices renumbered in `order` (new id -> old slot); the triangles in
  /// their order, or with space_order by their smallest new vertex id.
  std::vector<std::uint32_t> renumber(const std::vector<std::uint32_t>& order, bool space_order);
};

/// The elements of both sorted lists, sorted (e.g. two vertices' neighbours()).
std::vector<std::uint32_t> sorted_intersection(const std::vector<std::uint32_t>& a,
                                               const std::vector<std::uint32_t>& b);

/// The position (0, 1, 2) of vertex v in triangle t. \pre t holds v.
inline std::size_t corner_index(const Triangle& t, std::uint32_t v) {
  return t[0] == v ? 0 : (t[1] == v ? 1 : 2);
}

}  // namespace isopatch
