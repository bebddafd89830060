#pragma once
/// \file convex_meshing.hpp
/// What the projection mesher needs to set up a partition of convex cells (mesh_projection.cpp chooses
/// it): the planes of Settings::region or of Settings::cells, and the box they cover.

#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <optional>
#include <vector>

#include "partition/cell_partition.hpp"

namespace isopatch {

/// The region's half-spaces as unit planes (labels: their 0-based index).
std::vector<CellPlane> cell_planes(const ConvexRegion& region);

/// The box the convex partition covers: settings.box when given; else, for a region, the bounds of the
/// region grown by 0.1% of their diagonal when it is bounded (within 10^4 times the surface's box),
/// or the surface's own box when it is not; for given cells, the bounds of all cells, grown by 0.1%.
/// Empty when neither a region nor cells are set.
/// \throw SettingError("region" or "cells") when the region (or a cell) is empty inside the box (or
///        misses the surface's box), or, for given cells without a box, a cell is unbounded.
std::optional<Box> convex_meshing_box(const Surface& surface, const Settings& settings);

}  // namespace isopatch
