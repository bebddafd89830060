#pragma once
// The cut of a tile's mesh (tiles.hpp): its boundary, the edges in one triangle, as the tiles' passes
// find it.

#include <isopatch/mesh.hpp>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace isopatch::blocks {

/// The directed edge a -> b as one number.
inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{a} << 32) | b;
}

/// How often each directed edge occurs in the triangles of `mesh` (only those flagged in `kept`, when
/// given).
std::unordered_map<std::uint64_t, std::uint32_t> directed_edges(
    const Mesh& mesh, const std::vector<std::uint8_t>* kept = nullptr);

/// Per vertex of `mesh` (consistently oriented): whether it lies on an edge without its reverse (the cut).
std::vector<std::uint8_t> cut_vertices(const Mesh& mesh);

}  // namespace isopatch::blocks
