#pragma once
// Which boundary vertices of a surface cut open by its box may slide along the cut. A vertex on a
// boundary edge that lies on exactly one face of the box can move along the curve where f = 0 meets
// that face (and be merged into a boundary neighbour) without changing the cut; one on two or three
// faces (where the curve turns round a box edge or corner) or on none (a hole elsewhere) stays put.

#include <isopatch/geometry.hpp>

#include <vector>

#include "remesh/editable_mesh.hpp"

namespace isopatch {

/// Per vertex slot: the axis (0, 1, 2) of the one box face a locked vertex lies on, exactly (the
/// meshers clamp the cut to the box), or -1 for every other vertex.
std::vector<int> sliding_axes(const EditableMesh& mesh, const Box& box);

}  // namespace isopatch
