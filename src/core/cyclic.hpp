#pragma once
/// \file cyclic.hpp
/// Index arithmetic on cycles (loops of corners, polygon vertices, patch sides).

#include <cstddef>

namespace isopatch {

/// The index after k on a cycle of n elements (k < n): sides of a loop run from k to next(k, n).
constexpr std::size_t next(std::size_t k, std::size_t n) {
  return k + 1 == n ? 0 : k + 1;
}

}  // namespace isopatch
