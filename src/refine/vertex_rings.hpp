#pragma once
// The one-ring of every vertex of a triangle mesh in compressed rows: for each triangle corner, the
// next corner of that triangle. Around an interior vertex of an oriented manifold mesh this lists every
// neighbour exactly once (one per incident triangle); a boundary vertex misses one neighbour, which the
// relaxation never needs (boundary vertices slide along their curve or stay). 4 bytes per incident
// triangle and 4 per vertex.

#include <isopatch/mesh.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace isopatch::refine {

class VertexRings {
 public:
  /// \pre every index of `triangles` is below `vertex_count`.
  VertexRings(std::size_t vertex_count, std::span<const Triangle> triangles);

  std::span<const std::uint32_t> of(std::size_t v) const {
    return {neighbours_.data() + offsets_[v], neighbours_.data() + offsets_[v + 1]};
  }

 private:
  std::vector<std::uint32_t> offsets_;
  std::vector<std::uint32_t> neighbours_;
};

}  // namespace isopatch::refine
