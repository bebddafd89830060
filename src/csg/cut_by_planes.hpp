#pragma once
// A formula intersected with half-spaces: max(f, p_1, ..., p_k), the shape f < 0 cut by planes, as a
// formula of its own (its tape is f's with the planes appended), so that the crease analysis sees the
// planes' faces and the creases where f meets them (api/clipped_creases.hpp).

#include <isopatch/convex_region.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

namespace isopatch {

/// max(f, a x + b y + c z + d for each plane) as a formula surface over `box`, or null when `f` has no
/// expression. The planes are used as given (scale them to unit normals for distances).
SurfacePtr cut_by_planes(const Surface& f, const ConvexRegion& planes, const Box& box);

}  // namespace isopatch
