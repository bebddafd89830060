#pragma once
// The settings a composite meshed along its own curves refuses (mesh_composite.cpp; blocks of a
// composite, src/blocks).

#include <isopatch/settings.hpp>

namespace isopatch {

/// Settings that shape the octree, which the construction's curves replace, refused rather than
/// ignored when set to other than their defaults (min_depth, max_depth, max_cell_curvature,
/// refine_around). \throw SettingError naming the first such field.
void refuse_octree_settings(const Settings& settings);

/// Whether a composite meshed along its curves is refined (multiresolution): an explicit level above 1,
/// or the automatic level unless the paper's method alone (remesh 0) or a fixed segment count
/// (resolution) is asked for.
bool composite_refines(const Settings& settings);

}  // namespace isopatch
