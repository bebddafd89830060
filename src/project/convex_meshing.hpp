#pragma once
/// \file convex_meshing.hpp
/// The projection mesher over partitions of convex cells (convex_partitioner.hpp): a region's clipped
/// lattice, or cells given by the caller (Settings::region, Settings::cells).

#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <optional>
#include <vector>

#include "partition/convex_cell.hpp"

namespace isopatch {

/// The region's half-spaces as unit planes (labels: their 0-based index).
std::vector<CellPlane> cell_planes(const ConvexRegion& region);

/// The box the convex partition covers: settings.box when given; else the bounds of the region, or of
/// the given cells, grown by 0.1% of their diagonal. Empty when neither a region nor cells are set.
/// \throw SettingError("region" or "cells") when the region (or a cell) is empty inside the box, or,
///        without a box, unbounded (it reaches 10^4 times the surface's box).
std::optional<Box> convex_meshing_box(const Surface& surface, const Settings& settings);

/// Meshes f = 0 over the convex partition of the settings (settings.box as convex_meshing_box gave it).
/// \throw as mesh_projection, and SettingError("cells") when the given cells overlap or leave gaps.
Mesh mesh_convex(const Surface& surface, const Settings& settings, const Box& box, MeshStats* stats);

}  // namespace isopatch
