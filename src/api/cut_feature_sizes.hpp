#pragma once
// Sizes where the box or a region plane cuts the surface in features smaller than the edge length
// (docs/algorithms.md 4.11). Where a box face or plane is nearly tangent to f = 0, the curve where it
// cuts the surface turns within an edge (a small hole, a sharp turn) or runs close to another piece of
// the cut or to the face's own border (a thin strip of surface left between two box faces, a slit
// where a plane shaves a ridge). Triangles spanning such a feature at the requested edge length are
// slivers whatever the clean-up does; triangles of the feature's own size are not. This finds those
// places on every face and plane and returns a graded size field that is smaller there only.

#include <isopatch/convex_region.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <vector>

#include "api/graded_sizes.hpp"

namespace isopatch {

/// Tuning of the search (the defaults are what docs/algorithms.md 4.11 measured).
struct CutFeatureParams {
  double turn = 0.6;       ///< a cut curve turns at most this many radians per edge
  double width = 1.0;      ///< edges at most this many times the local width of a strip or slit
  double grading = 0.2;    ///< sizes grow by at most this much per unit distance (the clean-up: 0.3)
  double relevant = 0.5;   ///< sources only where the size is below this share of the edge length
  int max_samples = 1024;  ///< grid points per side of a face at most
};

/// Samples every face of `box` and every plane of `region` (within the box and the other planes) on a
/// grid of edge/4 (at most max_samples per side; blocks of 16 x 16 points whose interval enclosure of f
/// excludes 0 are skipped; a surface without enclosures, Surface::bound nullopt, has no sources), finds where
/// f changes sign along the grid lines (the cut curves), and at each such point measures the curve's
/// curvature within the plane (from the exact Hessian) and the width of the region on either side of it,
/// across the curve and within the plane, up to one edge length: the distance to the next cut curve, or to
/// the face's border when the curve does not itself reach that border nearby (a curve ending on a box edge at
/// a good angle is no feature). Its size is min(turn / curvature, width * width-share), at least `smallest`.
/// Deterministic (fixed grids and order; batches of f evaluated in parallel give the same values). f is
/// evaluated in the box only; points where f or its derivatives are not finite ask for nothing. Follows no
/// paper: it is the 2D analogue, on each cutting plane, of sizing by local feature size (Ruppert 1995). \pre
/// box.valid(), edge > 0, 0 < smallest <= edge; every plane of region has a normal. \throw what the surface
/// throws (a budget's LimitError); nothing else.
GradedSizes cut_feature_sizes(const Surface& surface, const Box& box, const ConvexRegion& region, double edge,
                              double smallest, const CutFeatureParams& params = {});

/// The sources of cut_feature_sizes alone (to add others before making the field).
std::vector<SizeSource> cut_feature_sources(const Surface& surface, const Box& box,
                                            const ConvexRegion& region, double edge, double smallest,
                                            const CutFeatureParams& params = {});

}  // namespace isopatch
