#pragma once
// The vertices the preview's local repair works on (the preview preset, CleanupEffort::local_only): those
// near a defect of the mesh, so that the repair costs in proportion to what needs fixing.

#include <cstdint>
#include <vector>

#include "remesh/editable_mesh.hpp"
#include "remesh/size_field.hpp"

namespace isopatch {

struct DefectThresholds {
  double cos_small_angle = 0.866;   ///< a triangle whose smallest angle has a larger cosine is a defect
  double split_factor = 4.0 / 3.0;  ///< an edge longer than this times its target size is a defect
  double collapse_factor = 0.35;    ///< an edge shorter than this times its target size is a defect
};

/// The live vertices of triangles with a small angle or an edge out of [collapse, split] times its size
/// (sizes.edge), and the vertices whose valence is not their target (valence_flips.hpp), grown by
/// `rings` rings of neighbours; ascending. \pre sizes.update(mesh) since the last change.
std::vector<std::uint32_t> vertices_near_defects(const EditableMesh& mesh, const SizeField& sizes,
                                                 const DefectThresholds& thresholds, int rings);

}  // namespace isopatch
