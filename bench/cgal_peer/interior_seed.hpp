#pragma once
/// \file interior_seed.hpp
/// A point well inside the solid f < 0, for meshers that start from an interior point.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <optional>

namespace isopatch::bench {

/// The sample of an n x n x n grid over `box` (cell centres) with the most negative estimated signed
/// distance f / |grad f|, or nullopt when no sample has f < 0 (non-finite samples are skipped).
/// \pre box.valid(), n >= 1
std::optional<Vec3> deepest_interior_sample(const Surface& surface, const Box& box, int n = 32);

}  // namespace isopatch::bench
