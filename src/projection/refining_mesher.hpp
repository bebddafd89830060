#pragma once
/// \file refining_mesher.hpp
/// The projection mesher's outer loop over any partition (Sipos & Salvi 2021, sec. 2: reject and
/// subdivide): build the partition, mesh every cell, split the cells whose patches were rejected and
/// mesh again, until every cell has a patch or a fallback fan. Knows partitions only through
/// cell_partition.hpp.

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/stage_settings.hpp>
#include <isopatch/surface.hpp>

#include "partition/cell_partition.hpp"
#include "projection/cell_mesher.hpp"
#include "surface/target_size.hpp"

namespace isopatch {

/// Meshes f = 0 over the partitions that `partitioner` builds. While no cell holds the surface, or
/// (automatic resolution, OctreeSettings::max_cell_curvature > 0) most starting cells are too curved, it
/// restarts one level finer. Cells longer than the size field allows, and cells whose patch or side is
/// rejected, are split (at most OctreeSettings::refinement_levels below the start, or down to the finest
/// level with a size field) for up to 8 rounds; what still fails is closed by fans.
/// \param sizes  the target sizes (size_spec of the settings)
/// \throw NoSurfaceError when no cell down to the finest level holds a sign change; LimitError on
///        cancel or beyond BudgetSettings::max_vertices; EvaluationError when f is not finite where needed.
Mesh mesh_refining(const Surface& surface, Partitioner& partitioner, const OctreeSettings& octree,
                   const CellMesherSettings& settings, const TargetSizes& sizes, MeshStats* stats);

}  // namespace isopatch
