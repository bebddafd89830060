#pragma once
// Local edits of a list of edges (splits, collapses) in parallel with one result for any number of threads,
// by the spatial blocks of flip_blocks.hpp: an edge whose two ends lie in one cube is edited by that
// cube's task, in the list's order; the cubes of one colour run concurrently (they are at least one
// cube apart, and an edit reads and writes only the rings of its edge's ends). The edges across the
// first grid's faces get their turn in a grid shifted by half a cube, and the few across both grids'
// faces last, one after the other.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "remesh/editable_mesh.hpp"
#include "remesh/flip_blocks.hpp"

namespace isopatch {

using EdgeList = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

/// The edges of `keyed` in ascending order of their keys (ties by the edge), each once per entry;
/// releases `keyed`.
inline EdgeList edges_by_key(
    std::vector<std::pair<double, std::pair<std::uint32_t, std::uint32_t>>>&& keyed) {
  std::sort(keyed.begin(), keyed.end());
  EdgeList edges(keyed.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) edges[i] = keyed[i].second;
  keyed = {};
  return edges;
}

/// Calls edit(a, b, k) for every (a, b) = work[k], each once: first the edges inside one cube of a grid
/// of cubes (flip_block_width), the cubes of one colour in parallel, each cube's edges in work's
/// order; then the rest inside one cube of the grid shifted by half a cube, the same way; then what is
/// left, in work's order. Returns how many calls returned true.
/// \pre edit(a, b, k) reads and writes only a, b, their neighbours, the triangles incident to them and
/// slots of its own (new slots numbered by k),
/// and nothing else that another call writes (a counter of its own, say, returned instead), and
/// touches only vertices within a few of the mesh's longest edges of a and b.
/// \post the same edits, in the same order within each cube, for any number of threads.
template <class Edit>
std::size_t edit_edges_in_blocks(const EditableMesh& mesh, const EdgeList& work, Edit edit) {
  using Index = std::vector<std::size_t>;
  Index pending(work.size());
  for (std::size_t i = 0; i < work.size(); ++i) pending[i] = i;
  const double width = flip_block_width(mesh);
  std::size_t edits = 0;
  for (const double shift : {0.0, 0.5}) {
    if (pending.empty() || !(width > 0.0)) break;
    const FlipBlocks blocks = make_flip_blocks(mesh, width, shift);
    if (blocks.members.size() <= 1) break;  // one cube: nothing to run side by side
    std::vector<Index> inside(blocks.members.size());
    Index across;
    for (const std::size_t i : pending) {
      const auto [a, b] = work[i];
      const std::uint32_t cube = blocks.block_of[a];
      if (cube != kNoBlock && cube == blocks.block_of[b])
        inside[cube].push_back(i);
      else
        across.push_back(i);
    }
    std::vector<std::size_t> per_cube(blocks.members.size(), 0);
    for (const std::vector<std::uint32_t>& cubes : blocks.colours)
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cubes.size(), 1), [&](const auto& range) {
        for (std::size_t k = range.begin(); k != range.end(); ++k) {
          const std::uint32_t cube = cubes[k];
          for (const std::size_t i : inside[cube])
            if (edit(work[i].first, work[i].second, i)) ++per_cube[cube];
        }
      });
    for (const std::size_t n : per_cube) edits += n;
    pending = std::move(across);
  }
  for (const std::size_t i : pending)
    if (edit(work[i].first, work[i].second, i)) ++edits;
  return edits;
}

}  // namespace isopatch
