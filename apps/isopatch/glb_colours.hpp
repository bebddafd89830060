#pragma once
// The COLOR_0 of a .glb written by the tool (isopatch mesh -o X.glb, the viewer's downloads): one
// field of the mesh on the renderer's colour maps, in linear RGB.

#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <string>
#include <vector>

namespace isopatch::cli {

/// The field names a .glb can be coloured by (the names attach_fields() gives), and "none".
inline constexpr const char* kGlbColourFields =
    "mean_curvature, mean_curvature_exact, gaussian_curvature, gaussian_curvature_exact, distance or none";

/// \throw InputError unless `field` is one of kGlbColourFields (checked before any work is done).
void check_colour_field(const std::string& field);

/// Colours for `mesh` from its attribute `field` (the renderer's diverging map over a robust range;
/// "distance": the sequential map of |distance|), or, when the mesh does not carry it, from the same
/// field computed against `surface` (when given; discrete curvature needs none). Empty for "none".
/// \throw InputError for an unknown field, or one that needs a surface when none is given.
std::vector<Vec3> glb_colours(const Mesh& mesh, const Surface* surface, const std::string& field);

}  // namespace isopatch::cli
