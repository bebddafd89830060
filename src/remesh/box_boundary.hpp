#pragma once
// Which boundary vertices of a surface cut open by its box, or by the planes of a region, may slide
// along the cut. A vertex on a boundary edge that lies on exactly one face of the box can move along
// the curve where f = 0 meets that face (and be merged into a boundary neighbour) without changing the
// cut; one on two or three faces (where the curve turns round a box edge or corner) or on none (a hole
// elsewhere) stays put. The same holds for a vertex on exactly one plane of a region (and on no box
// face): it slides on its plane, Newton steps along the in-plane gradient, snapped back into the plane.

#include <isopatch/convex_region.hpp>
#include <isopatch/geometry.hpp>

#include <cmath>
#include <optional>
#include <vector>

#include "remesh/editable_mesh.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

/// A plane of a region with a unit normal: n . x + offset = 0 on it, <= 0 inside.
struct CutPlane {
  Vec3 normal = Vec3::UnitX();
  double offset = 0.0;
  double distance(const Vec3& p) const { return normal.dot(p) + offset; }
};

/// Per vertex slot: the axis (0, 1, 2) of the one box face a locked vertex lies on, exactly (the
/// meshers clamp the cut to the box), when it lies on none of the region's `planes` (within
/// `tolerance`: where the cut turns from a box face onto a plane it stays put); -1 for every other.
std::vector<int> sliding_axes(const EditableMesh& mesh, const Box& box,
                              const std::vector<CutPlane>& planes = {}, double tolerance = 0.0);

/// Whether p lies on a face of `box` (exactly), false without a box.
inline bool on_box_face(const std::optional<Box>& box, const Vec3& p) {
  return box && ((p.array() == box->lo.array()).any() || (p.array() == box->hi.array()).any());
}

/// Whether p lies within `margin` of plane k (false for k < 0).
inline bool on_cut_plane(const std::vector<CutPlane>& planes, int k, const Vec3& p, double margin) {
  return k >= 0 && std::abs(planes[static_cast<std::size_t>(k)].distance(p)) <= margin;
}

/// The region's planes with unit normals. \pre every plane has a normal (validate_region).
std::vector<CutPlane> cut_planes(const ConvexRegion& region);

/// Per vertex slot: the index of the one plane a locked vertex lies on (within `tolerance`) when it
/// lies on no face of `box` (may be null), or -1.
std::vector<int> sliding_planes(const EditableMesh& mesh, const std::vector<CutPlane>& planes, const Box* box,
                                double tolerance);

/// Moves p onto f = 0 (to `tolerance`) within plane `k` of `planes` (Newton along the in-plane
/// gradient, steps at most max_step, the point put back into the plane after each step). False when it
/// does not converge, or ends beyond another of the planes or within `margin` of one.
/// \throw EvaluationError if f or grad f is not finite on the way.
bool project_onto_cut_plane(const Sampler& f, Vec3& p, const std::vector<CutPlane>& planes, std::size_t k,
                            double tolerance, double margin, double max_step, Vec3* gradient);

}  // namespace isopatch
