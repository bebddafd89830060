#pragma once
// Meshing in a rotated frame (Settings::frame): the surface, box, region and cells are seen in the
// frame (rotated_surface.hpp), the partition and the clean-up run there, and the mesh is rotated back.

#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <functional>

namespace isopatch {

using Mesher = std::function<Mesh(const Surface&, const Settings&, MeshStats*)>;

/// Meshes with `mesher` in the frame of settings.frame (which must be set). The frame's box is the
/// bounds of the user's box (settings.box, else the surface's) in the frame; when, without given
/// cells, that mesh leaves the user's box (the surface is cut open by it), the box's six planes join
/// the region's and the mesh is made again, so the cut lies on the box faces. The default edge
/// length (or largest size) is that of the user's box.
Mesh mesh_in_frame(const Surface& surface, const Settings& settings, MeshStats* stats, const Mesher& mesher);

}  // namespace isopatch
