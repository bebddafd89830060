// Valence-driven edge flips with glide chains, see valence_flips.hpp.
#include "remesh/valence_flips.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "remesh/flip_blocks.hpp"

namespace isopatch {

double valence_six_share(const EditableMesh& mesh) {
  std::size_t free = 0, six = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_slots(); ++v)
    if (mesh.alive(v) && !mesh.locked[v]) {
      ++free;
      if (mesh.valence(v) == 6) ++six;
    }
  return free == 0 ? 1.0 : static_cast<double>(six) / static_cast<double>(free);
}

int flip_energy_change(const EditableMesh& mesh, const EditableMesh::Edge& e) {
  const auto deviation = [&](std::uint32_t v, int change) {
    const int d = static_cast<int>(mesh.valence(v)) + change - target_valence(mesh, v);
    return d * d;
  };
  const int before = deviation(e.a, 0) + deviation(e.b, 0) + deviation(e.c, 0) + deviation(e.d, 0);
  const int after = deviation(e.a, -1) + deviation(e.b, -1) + deviation(e.c, 1) + deviation(e.d, 1);
  return after - before;
}

namespace {

using VertexPair = std::pair<std::uint32_t, std::uint32_t>;

bool same_edge(const VertexPair& p, std::uint32_t a, std::uint32_t b) {
  return (p.first == a && p.second == b) || (p.first == b && p.second == a);
}

class GlideSearch {
 public:
  GlideSearch(EditableMesh& mesh, const FlipIfValid& flip, const GlideLimits& limits)
      : mesh_(mesh),
        flip_(flip),
        limits_(limits),
        around_(static_cast<std::size_t>(std::max(limits.depth, 1))) {}

  /// Flips kept by a chain starting with the flip of a-b (0 when none was found).
  std::size_t start(std::uint32_t a, std::uint32_t b) {
    if (!mesh_.alive(a) || !mesh_.alive(b)) return 0;
    const auto e = mesh_.interior_edge(a, b);
    if (!e) return 0;
    const int change = flip_energy_change(mesh_, *e);
    if (change < 0 || change > limits_.max_debt) return 0;
    budget_ = limits_.budget;
    return chain(*e, limits_.depth, change);
  }

 private:
  /// An edge near the last flip and the energy change of flipping it. Only the vertex pair is kept: an
  /// undone chain restores the triangles' vertices but may swap the ids of the two triangles it used.
  struct Candidate {
    VertexPair edge;
    int change;
  };

  /// The interior edges at the four vertices of the flip just made (now c-d), once each, without c-d.
  /// Read from the triangle fan of each vertex alone: edge v-w is (v, w, c) in one triangle and
  /// (w, v, d) in another, both incident to v.
  /// Written into `out` (cleared first); the fans' scratch lists are members, so no allocation once
  /// they have grown.
  void candidates_around(const EditableMesh::Edge& e, std::vector<Candidate>& out) {
    out.clear();
    const std::uint32_t quad[4] = {e.a, e.b, e.c, e.d};
    const auto in_quad = [&](std::uint32_t w) { return std::find(quad, quad + 4, w) != quad + 4; };
    std::vector<std::uint32_t>& next = next_;
    std::vector<std::uint32_t>& previous = previous_;
    for (std::uint32_t v : quad) {
      next.clear();
      previous.clear();
      for (std::uint32_t t : mesh_.incident[v]) {
        const auto& tri = mesh_.triangles[t];
        const std::size_t i = corner_index(tri, v);
        next.push_back(tri[(i + 1) % 3]);
        previous.push_back(tri[(i + 2) % 3]);
      }
      for (std::size_t k = 0; k < next.size(); ++k) {
        const std::uint32_t w = next[k], c = previous[k];
        if ((in_quad(w) && w < v) || same_edge({v, w}, e.c, e.d)) continue;
        const auto back = std::find(previous.begin(), previous.end(), w);
        if (back == previous.end()) continue;  // w -> v in no triangle: a boundary edge
        const std::uint32_t d = next[static_cast<std::size_t>(back - previous.begin())];
        if (d == c) continue;
        out.push_back({{v, w}, flip_energy_change(mesh_, EditableMesh::Edge{v, w, c, d, 0, 0})});
      }
    }
  }

  /// Flips e (its energy change brought the chain's debt to `debt`), then looks at the edges around its
  /// four vertices for a flip that takes the total below zero, or (depth > 1) one that keeps the debt
  /// within limits.max_debt to continue from. Undoes e when nothing is found.
  std::size_t chain(const EditableMesh::Edge& e, int depth, int debt) {
    if (budget_-- <= 0 || !flip_(e, true)) return 0;
    // One candidate list per chain depth, kept between chains (sized once: a deeper call must not
    // move the lists the shallower ones are iterating).
    std::vector<Candidate>& around = around_[static_cast<std::size_t>(limits_.depth - depth)];
    candidates_around(e, around);
    for (const Candidate& next : around) {
      if (next.change + debt >= 0) continue;
      if (const auto edge = mesh_.interior_edge(next.edge.first, next.edge.second);
          edge && flip_(*edge, false))
        return 2;
    }
    if (depth > 1) {
      for (const Candidate& next : around) {
        const int total = next.change + debt;
        if (total < 0 || total > limits_.max_debt) continue;
        const auto edge = mesh_.interior_edge(next.edge.first, next.edge.second);
        if (!edge) continue;
        if (const std::size_t kept = chain(*edge, depth - 1, total)) return kept + 1;
      }
    }
    mesh_.flip(*mesh_.interior_edge(e.c, e.d));  // back to a-b: the flip of c-d restores both triangles
    return 0;
  }

  EditableMesh& mesh_;
  const FlipIfValid& flip_;
  const GlideLimits& limits_;
  int budget_ = 0;
  std::vector<std::vector<Candidate>> around_;  ///< per chain depth
  std::vector<std::uint32_t> next_, previous_;  ///< scratch of candidates_around
};

/// The edges whose flip changes the valence of an irregular vertex among `vertices`: those at it and
/// those of its link (a neutral flip needs one; with four vertices of target valence a flip costs 4), as
/// (smaller, larger), sorted, each once.
std::vector<VertexPair> edges_near_irregular_vertices(const EditableMesh& mesh,
                                                      const std::vector<std::uint32_t>& vertices) {
  std::vector<VertexPair> list;
  for (std::uint32_t v : vertices) {
    if (!mesh.alive(v) || static_cast<int>(mesh.valence(v)) == target_valence(mesh, v)) continue;
    // Per triangle (v, x, y) in its winding: the spoke v-x and the link edge x-y. Each spoke is the
    // first edge of exactly one of v's triangles (the other one holds it as y-v), so v adds no
    // duplicates of its own; those shared with a nearby irregular vertex go in the sort below.
    for (std::uint32_t t : mesh.incident[v]) {
      const auto& tri = mesh.triangles[t];
      const std::size_t i = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
      const std::uint32_t x = tri[(i + 1) % 3], y = tri[(i + 2) % 3];
      list.emplace_back(std::min(v, x), std::max(v, x));
      list.emplace_back(std::min(x, y), std::max(x, y));
    }
    // On a boundary the last spoke is the second edge of the fan's end triangle only.
    if (mesh.locked[v])
      for (std::uint32_t t : mesh.incident[v]) {
        const auto& tri = mesh.triangles[t];
        const std::size_t i = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
        const std::uint32_t y = tri[(i + 2) % 3];
        list.emplace_back(std::min(v, y), std::max(v, y));
      }
  }
  std::sort(list.begin(), list.end());
  list.erase(std::unique(list.begin(), list.end()), list.end());
  return list;
}

/// Greedy flips, then glide chains (limits.passes sweeps) from the edges near the irregular vertices
/// of `vertices`, keeping only the start edges that `keep` accepts; `flip` decides every flip. With
/// `refused`: `*refused` is set by `flip` when it refused a flip for lying outside the region, and the
/// start edges whose flip or chain met such a refusal (and found nothing) are appended to `retry`.
template <class Keep>
std::size_t flip_region(EditableMesh& mesh, const FlipIfValid& flip, const GlideLimits& limits,
                        const std::vector<std::uint32_t>& vertices, Keep keep, bool* refused,
                        std::vector<VertexPair>* retry) {
  const auto starts = [&] {
    std::vector<VertexPair> list = edges_near_irregular_vertices(mesh, vertices);
    std::erase_if(list, [&](const VertexPair& edge) { return !keep(edge); });
    return list;
  };
  const auto note = [&](const VertexPair& edge, bool found) {
    if (refused && *refused && !found) retry->push_back(edge);
  };
  std::size_t flips = 0;
  for (const auto& [a, b] : starts()) {
    if (refused) *refused = false;
    const auto e = mesh.interior_edge(a, b);
    const bool found = e && flip_energy_change(mesh, *e) < 0 && flip(*e, false);
    flips += found ? 1 : 0;
    note({a, b}, found);
  }
  GlideSearch search(mesh, flip, limits);
  for (int pass = 0; pass < limits.passes; ++pass) {
    std::size_t kept = 0;
    for (const auto& [a, b] : starts()) {
      if (refused) *refused = false;
      const std::size_t chain = search.start(a, b);
      kept += chain;
      note({a, b}, chain > 0);
    }
    flips += kept;
    if (kept == 0) break;
  }
  return flips;
}

/// One grid of blocks: every cube's flips confined to the cube, the cubes of one colour in parallel.
/// Only start edges that `keep` accepts; those that met a cube's face and found nothing are returned in
/// `retry` (sorted, each once).
template <class Keep>
std::size_t flip_blocks(EditableMesh& mesh, const FlipIfValid& flip, const GlideLimits& limits,
                        const FlipBlocks& blocks, Keep keep, std::vector<VertexPair>& retry) {
  std::vector<std::size_t> flips(blocks.members.size(), 0);
  std::vector<std::vector<VertexPair>> retries(blocks.members.size());
  for (const std::vector<std::uint32_t>& cubes : blocks.colours)
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cubes.size(), 1), [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const std::uint32_t cube = cubes[i];
        bool refused = false;
        const auto inside = [&](std::uint32_t v) { return blocks.block_of[v] == cube; };
        const FlipIfValid confined = [&](const EditableMesh::Edge& e, bool neutral) {
          if (!(inside(e.a) && inside(e.b) && inside(e.c) && inside(e.d))) {
            refused = true;
            return false;
          }
          return flip(e, neutral);
        };
        flips[cube] =
            flip_region(mesh, confined, limits, blocks.members[cube], keep, &refused, &retries[cube]);
      }
    });
  std::size_t total = 0;
  retry.clear();
  for (std::size_t cube = 0; cube < flips.size(); ++cube) {
    total += flips[cube];
    retry.insert(retry.end(), retries[cube].begin(), retries[cube].end());
  }
  std::sort(retry.begin(), retry.end());
  retry.erase(std::unique(retry.begin(), retry.end()), retry.end());
  return total;
}

}  // namespace

std::size_t flip_towards_valence_six(EditableMesh& mesh, const FlipIfValid& flip, const GlideLimits& limits) {
  const double width = flip_block_width(mesh);
  const FlipBlocks first = width > 0.0 ? make_flip_blocks(mesh, width, 0.0) : FlipBlocks{};
  if (first.members.size() <= 1) {  // one cube (or no edge): the whole mesh in one region
    std::vector<std::uint32_t> all;
    for (std::uint32_t v = 0; v < mesh.vertex_slots(); ++v)
      if (mesh.alive(v)) all.push_back(v);
    return flip_region(
        mesh, flip, limits, all, [](const VertexPair&) { return true; }, nullptr, nullptr);
  }
  // The first grid, then the edges that met its faces again in a grid shifted by half a cube (where
  // they lie well inside a cube).
  std::vector<VertexPair> retry, unused;
  std::size_t flips = flip_blocks(
      mesh, flip, limits, first, [](const VertexPair&) { return true; }, retry);
  if (!retry.empty()) {
    const FlipBlocks second = make_flip_blocks(mesh, width, 0.5);
    flips += flip_blocks(
        mesh, flip, limits, second,
        [&](const VertexPair& edge) { return std::binary_search(retry.begin(), retry.end(), edge); }, unused);
  }
  return flips;
}

}  // namespace isopatch
