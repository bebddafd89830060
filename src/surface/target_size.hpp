#pragma once
// The target edge length at a point, shared by the projection mesher (cell sizes, segments per side)
// and the remesher (split and collapse thresholds): a fixed length, or the smallest of a curvature size
// for a chordal error bound and a caller's size field, clamped to [smallest, largest].

#include <isopatch/stage_settings.hpp>
#include <isopatch/surface.hpp>

#include <functional>
#include <optional>

namespace isopatch {

/// The target size at p. \throw InputError when the caller's size field gives a value that is not
/// positive and finite.
double target_size(const Surface& surface, const TargetSizes& spec, const Vec3& p);

}  // namespace isopatch
