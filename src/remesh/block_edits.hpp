#pragma once
// Local edits of a list of edges (splits, collapses) in parallel with one result for any number of
// threads, by spatial blocks as in flip_blocks.hpp: an edge whose two ends lie in one cube is edited by
// that cube's task, in the list's order; the cubes of one colour (the parities of their grid
// coordinates) run concurrently: they are at least one cube apart, and an edit reads and writes only
// the rings of its edge's ends. The edges across the first grid's faces get their turn in a grid
// shifted by half a cube, and the few across both grids' faces last, one after the other. Only the
// listed edges' ends are binned, so the cost follows the list, not the mesh.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "remesh/editable_mesh.hpp"

namespace isopatch {

using EdgeList = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
using KeyedEdge = std::pair<double, std::pair<std::uint32_t, std::uint32_t>>;  ///< (key, (a, b))

/// The edges of `keyed` in ascending order of their keys (ties by the edge), each once per entry;
/// releases `keyed`.
EdgeList edges_by_key(std::vector<KeyedEdge>&& keyed);

/// What list_keyed_edges found.
struct KeyedEdges {
  std::vector<KeyedEdge> keyed;  ///< (key, (a, b)) in (a, b) order
  double longest = 0.0;          ///< the longest live edge of the whole mesh
};

/// Vertices per task of list_keyed_edges: fixed, so the pieces (and their order) do not depend on the
/// number of threads.
inline constexpr std::size_t kEdgeListBlock = 2048;

/// Every live edge (a, b), a < b, for which key(a, b, length) returns a key (a std::optional<double>),
/// with that key, in the order of EditableMesh::edges(), and the longest live edge. The vertices go in
/// fixed blocks in parallel, joined in order: the same list for any number of threads. `key` may run
/// concurrently (it only reads).
template <class Key>
KeyedEdges list_keyed_edges(const EditableMesh& mesh, Key key) {
  const std::size_t slots = mesh.vertex_slots();
  const std::size_t blocks = (slots + kEdgeListBlock - 1) / kEdgeListBlock;
  std::vector<std::vector<KeyedEdge>> pieces(blocks);
  std::vector<double> longest(blocks, 0.0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1), [&](const auto& range) {
    std::vector<std::uint32_t> larger;
    for (std::size_t block = range.begin(); block != range.end(); ++block) {
      const std::size_t end = std::min(slots, (block + 1) * kEdgeListBlock);
      for (std::size_t v = block * kEdgeListBlock; v < end; ++v) {
        const auto a = static_cast<std::uint32_t>(v);
        mesh.larger_neighbours(a, larger);
        for (const std::uint32_t b : larger) {
          const double length = (mesh.positions[a] - mesh.positions[b]).norm();
          longest[block] = std::max(longest[block], length);
          if (const auto k = key(a, b, length)) pieces[block].push_back({*k, {a, b}});
        }
      }
    }
  });
  KeyedEdges out;
  std::size_t total = 0;
  for (const auto& piece : pieces) total += piece.size();
  out.keyed.reserve(total);
  for (std::size_t block = 0; block < blocks; ++block) {
    out.keyed.insert(out.keyed.end(), pieces[block].begin(), pieces[block].end());
    out.longest = std::max(out.longest, longest[block]);
  }
  return out;
}

/// The edges of a list (by index) that lie inside one cube of a grid, grouped by cube and by colour.
struct EdgeCubes {
  std::vector<std::uint32_t> order;  ///< indices into the list, by colour, then cube, then ascending
  /// Per colour: the cubes' runs [begin, end) in `order`.
  std::array<std::vector<std::pair<std::size_t, std::size_t>>, 8> runs;
  std::vector<std::uint32_t> across;  ///< indices whose two ends lie in different cubes, ascending
};

/// Bins the live ends of work[i] (i in `pending`, ascending) into cubes of side `width` (> 0) on a grid
/// whose origin is the lower corner of those ends, moved by shift * width along every axis.
/// Deterministic: depends on the positions alone.
EdgeCubes edge_cubes(const EditableMesh& mesh, const EdgeList& work,
                     const std::vector<std::uint32_t>& pending, double width, double shift);

/// The side of the cubes for edits on a mesh whose longest live edge is `longest_edge`.
double edit_block_width(double longest_edge);

/// Calls edit(a, b, k) for every (a, b) = work[k], each once: first the edges inside one cube of a grid
/// of cubes of edit_block_width(longest_edge), the cubes of one colour in parallel, each cube's edges in
/// work's order; then the rest inside one cube of the grid shifted by half a cube, the same way; then
/// what is left, in work's order. Returns how many calls returned true.
/// \pre longest_edge is at least the longest live edge of the mesh; edit(a, b, k) reads and writes only
/// a, b, their neighbours, the triangles incident to them and slots of its own (new slots numbered by
/// k), and nothing else that another call writes (a counter, say: return true instead).
/// \post the same edits, in the same order within each cube, for any number of threads.
template <class Edit>
std::size_t edit_edges_in_blocks(const EditableMesh& mesh, const EdgeList& work, double longest_edge,
                                 Edit edit) {
  std::vector<std::uint32_t> pending(work.size());
  for (std::size_t i = 0; i < work.size(); ++i) pending[i] = static_cast<std::uint32_t>(i);
  const double width = edit_block_width(longest_edge);
  std::size_t edits = 0;
  for (const double shift : {0.0, 0.5}) {
    if (pending.empty() || !(width > 0.0)) break;
    const EdgeCubes cubes = edge_cubes(mesh, work, pending, width, shift);
    for (const auto& runs : cubes.runs) {
      std::vector<std::size_t> per_cube(runs.size(), 0);
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, runs.size(), 1), [&](const auto& range) {
        for (std::size_t r = range.begin(); r != range.end(); ++r)
          for (std::size_t j = runs[r].first; j != runs[r].second; ++j) {
            const std::uint32_t i = cubes.order[j];
            if (edit(work[i].first, work[i].second, std::size_t{i})) ++per_cube[r];
          }
      });
      for (const std::size_t n : per_cube) edits += n;
    }
    pending = cubes.across;
  }
  for (const std::uint32_t i : pending)
    if (edit(work[i].first, work[i].second, std::size_t{i})) ++edits;
  return edits;
}

}  // namespace isopatch
