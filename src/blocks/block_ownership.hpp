#pragma once
/// \file block_ownership.hpp
/// Which block owns each shared item of a base cut into blocks, and its rank among that block's items:
/// the numbering rule of blocks.hpp (the lowest block beside an item owns it; a block's items are
/// ranked in ascending base order). Recomputed by every block from the base alone.

#include <isopatch/mesh.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include "refine/base_edges.hpp"

namespace isopatch::blocks {

struct Ownership {
  std::vector<std::uint32_t> vertex_owner, vertex_rank;  ///< per base vertex
  std::vector<std::uint32_t> edge_owner, edge_rank;      ///< per base edge (refine::base_edges numbering)
  std::vector<std::uint32_t> triangle_rank;              ///< per base triangle, among its block's
  /// Per block: base vertices, base edges and base triangles it owns.
  std::vector<std::uint64_t> vertices, edges, triangles;
};

/// The ownership of `base` (edges = refine::base_edges(base)) cut by `triangle_block` into `blocks`.
/// \pre every triangle_block value < blocks; every base vertex is used by a triangle (a vertex used by
///      none is owned by block 0).
Ownership ownership(const Mesh& base, const refine::BaseEdges& edges,
                    std::span<const std::uint32_t> triangle_block, int blocks);

}  // namespace isopatch::blocks
