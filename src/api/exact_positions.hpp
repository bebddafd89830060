#pragma once
// Vertices found again by the exact bits of their positions: the clean-up holds a boundary bit for bit, so
// a piece cleaned up on its own (a planar cap, a trimmed face, a part of a mesh) is put back by looking its
// held vertices up by position.

#include <isopatch/geometry.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <unordered_map>

namespace isopatch {

/// FNV-1a over the bits of the three coordinates.
struct PositionHash {
  std::size_t operator()(const Vec3& p) const {
    std::uint64_t h = 1469598103934665603ULL;
    for (int k = 0; k < 3; ++k) h = (h ^ std::bit_cast<std::uint64_t>(p[k])) * 1099511628211ULL;
    return static_cast<std::size_t>(h);
  }
};

/// A map from exact positions (equal coordinates, as the clean-up leaves held vertices) to T.
template <class T>
using ExactPositionMap = std::unordered_map<Vec3, T, PositionHash>;

}  // namespace isopatch
