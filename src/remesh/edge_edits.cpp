// Edge splits and collapses of the surface-bound clean-up, see edge_edits.hpp.
#include "remesh/edge_edits.hpp"

#include <optional>
#include <utility>
#include <vector>

#include "remesh/block_edits.hpp"
#include "remesh/box_boundary.hpp"
#include "remesh/editable_mesh.hpp"
#include "remesh/incidence_lists.hpp"

namespace isopatch::cleanup {

bool try_split(RemeshRun& run, std::uint32_t a, std::uint32_t b, std::uint32_t m, std::uint32_t t) {
  const auto e = run.mesh.interior_edge(a, b);
  if (!e) return false;
  Vec3 p = 0.5 * (run.mesh.positions[a] + run.mesh.positions[b]);
  Vec3 n;
  if (!run.project(p, n, run.length(a, b))) return false;
  const auto& P = run.mesh.positions;
  const auto& N = run.mesh.normals;
  if (!run.triangle_ok(P[e->a], p, P[e->c], N[e->a], n, N[e->c]) ||
      !run.triangle_ok(p, P[e->b], P[e->c], n, N[e->b], N[e->c]) ||
      !run.triangle_ok(P[e->b], p, P[e->d], N[e->b], n, N[e->d]) ||
      !run.triangle_ok(p, P[e->a], P[e->d], n, N[e->a], N[e->d]))
    return false;
  run.mesh.split(*e, p, n, m, t);
  return true;
}

void split_long_edges(RemeshRun& run) {
  run.check_cancel();
  KeyedEdges listed = list_keyed_edges(run.mesh, [&run](std::uint32_t a, std::uint32_t b, double l) {
    return l > kSplitFactor * run.sizes.edge(a, b) ? std::optional<double>(-l) : std::nullopt;
  });
  split_listed(run, edges_by_key(std::move(listed.keyed)), listed.longest);
}

std::size_t split_listed(RemeshRun& run, const EdgeList& edges, double longest) {
  const auto slots = run.mesh.add_split_slots(edges.size());  // (first vertex, first triangle)
  const std::uint32_t first_vertex = slots.first, first_triangle = slots.second;
  const std::size_t splits =
      edit_edges_in_blocks(run.mesh, edges, longest, [&](std::uint32_t a, std::uint32_t b, std::size_t k) {
        return try_split(run, a, b, first_vertex + static_cast<std::uint32_t>(k),
                         first_triangle + 2 * static_cast<std::uint32_t>(k));
      });
  run.stats.splits += splits;
  return splits;
}

bool try_collapse(RemeshRun& run, std::uint32_t a, std::uint32_t b, double max_length, bool repair) {
  if (run.mesh.locked[a] && run.mesh.locked[b]) return try_collapse_boundary(run, a, b, max_length);
  if (run.mesh.locked[a]) std::swap(a, b);
  const auto e = run.mesh.interior_edge(a, b);
  if (!e) return false;
  // Link condition: a and b share exactly the neighbours c and d.
  const std::vector<std::uint32_t> na = run.mesh.neighbours(a), nb = run.mesh.neighbours(b);
  if (sorted_intersection(na, nb).size() != 2) return false;
  const auto least = [&](std::uint32_t v) { return repair ? run.fewest(v) : 3u; };
  if (run.mesh.valence(e->c) <= least(e->c) || run.mesh.valence(e->d) <= least(e->d)) return false;
  if (na.size() + nb.size() - 4 > 9) return false;
  Vec3 p = run.mesh.positions[b], n = run.mesh.normals[b];
  if (!run.mesh.locked[b]) {
    p = 0.5 * (run.mesh.positions[a] + run.mesh.positions[b]);
    if (!run.project(p, n, run.length(a, b))) return false;
  }
  for (const auto* list : {&na, &nb})
    for (std::uint32_t x : *list)
      if (x != a && x != b && (run.mesh.positions[x] - p).norm() > max_length) return false;
  // Every remaining triangle of a or b gets the merged vertex at (p, n); under the link condition
  // none holds both.
  for (std::uint32_t v : {a, b})
    for (std::uint32_t t : run.mesh.incident[v])
      if (t != e->t_ab && t != e->t_ba && !run.triangle_ok_with(t, v, p, n)) return false;
  run.mesh.collapse(*e, p, n);
  return true;
}

bool try_collapse_boundary(RemeshRun& run, std::uint32_t a, std::uint32_t b, double max_length) {
  if (run.settings.hold_cut) return false;
  // Vertices within rounding of each other (crossings of segments at one lattice point) merge: none moves.
  const bool same = run.length(a, b) <= 1e-9 * max_length;
  if (run.slide_axis(a) < 0 && run.slide_plane(a) < 0) std::swap(a, b);
  const int axis = run.slide_axis(a), plane = run.slide_plane(a);
  const auto on_same_cut = [&](std::uint32_t v) {
    return axis >= 0 ? run.mesh.positions[v][axis] == run.mesh.positions[a][axis]
                     : on_cut_plane(run.planes, plane, run.mesh.positions[v], run.plane_margin());
  };
  if (!same && !on_same_cut(b)) return false;
  const auto e = run.mesh.boundary_edge(a, b);
  // An ear (a in one triangle) goes with its triangle when all three corners lie on the same cut: the
  // boundary then runs b - c, still along it (the raw mesh leaves such ears where several crossings
  // of lattice segments fall within rounding of one lattice point on a box face).
  if (!e || (run.mesh.incident[a].size() < 2 && !on_same_cut(e->c)) || run.mesh.valence(e->c) <= 3)
    return false;
  if (run.mesh.common_neighbours(a, b) != std::vector<std::uint32_t>{e->c}) return false;
  const Vec3& p = run.mesh.positions[b];
  for (std::uint32_t x : run.mesh.neighbours(a))
    if (!same && x != b && (run.mesh.positions[x] - p).norm() > max_length) return false;
  for (std::uint32_t t : run.mesh.incident[a])
    if (!same && t != e->t && !run.triangle_ok_with(t, a, p, run.mesh.normals[b])) return false;
  run.mesh.collapse_boundary(*e);
  return true;
}

void collapse_short_edges(RemeshRun& run) {
  run.check_cancel();
  KeyedEdges listed = list_keyed_edges(run.mesh, [&run](std::uint32_t a, std::uint32_t b, double l) {
    return l < run.collapse_factor() * run.sizes.edge(a, b) ? std::optional<double>(l) : std::nullopt;
  });
  const double longest = listed.longest;
  const EdgeList edges = edges_by_key(std::move(listed.keyed));
  // Shortest first within each block; a collapse reads and writes only the rings of its edge's ends.
  run.stats.collapses +=
      edit_edges_in_blocks(run.mesh, edges, longest, [&run](std::uint32_t a, std::uint32_t b, std::size_t) {
        if (!run.mesh.alive(a) || !run.mesh.alive(b) || !run.mesh.adjacent(a, b)) return false;
        const double h = run.sizes.edge(a, b);
        if (run.length(a, b) >= run.collapse_factor() * h) return false;
        return try_collapse(run, a, b, kSplitFactor * h);
      });
}

}  // namespace isopatch::cleanup
