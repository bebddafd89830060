#pragma once
// Sizes where f = 0 itself turns within an edge (docs/algorithms.md 4.12): the rim of a flat ellipsoid,
// a tube thinner than an edge, a blend of small radius. Triangles at the requested edge length cannot
// follow such a turn (they fold, or become slivers that the clean-up cannot mend); triangles of a
// fraction of the local radius of curvature can. This finds those places before meshing, by interval
// arithmetic over an octree of the box, and returns sources for a graded size field (graded_sizes.hpp).

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <vector>

#include "api/graded_sizes.hpp"

namespace isopatch {

/// Tuning of the search (the defaults are what docs/algorithms.md 4.12 measured).
struct CurvatureFeatureParams {
  double turn = 0.4;       ///< edges turn at most this many radians (sizes turn / kappa_max)
  double relevant = 0.25;  ///< sources only where the size is below this share of the edge length
  /// Sizes grow by at most this much per unit distance from a rim: gentler than the clean-up (0.3), as the
  /// surface's curvature falls off across a rim over a few of its radii (at 0.3 triangles of 16-19
  /// degrees were left where the size changes within one of them; at 0.2 none under 21).
  double grading = 0.2;
  double start_edges = 4.0;  ///< the search starts with cubes of this many edge lengths
  double coarse_turn = 3.0;  ///< a cube of side s may turn by turn * clamp(s / (relevant * edge), 1, this)
  double finest_share = 1.0 / 512.0;  ///< cubes are not split below this share of the edge length
  std::size_t max_cells = 1u << 21;   ///< cubes examined per level at most (then the level is the last)
};

/// What the search found and spent.
struct CurvatureFeatureSearch {
  std::vector<SizeSource> sources;  ///< in a fixed order (octree level, then cube order)
  bool searched = false;            ///< false when the surface has no interval enclosures
};

/// Searches `box` for places where f = 0 turns by more than params.turn within a cube of one edge length.
/// Cubes (from start_edges edge lengths, clipped to the box) whose interval enclosure of f excludes 0
/// are dropped; of the others, the enclosure of grad f bounds the normal cone: a cube of side s whose
/// normals may turn by more than turn * clamp(s / (relevant * edge), 1, coarse_turn) is split, down to
/// finest_share edge lengths; where grad f may vanish (a singular point, or the inside of a thin shell where
/// its two sheets' gradients meet) the cube is left to the singular-point search. At each cube of side below
/// one edge that stops, its centre is moved onto f = 0 (Newton, steps of at most its side); if it lands in
/// the cube, the largest principal curvature kappa there asks for size turn / kappa (at least `smallest`),
/// kept when below relevant * edge. A surface without enclosures (Surface::gradient_bound nullopt) is not
/// searched. Deterministic: each level's cubes are examined in parallel and gathered in order.
/// Follows no paper: the normal-cone test is that of the octree of Sipos & Salvi 2021 (sec. 2), used
/// to localise curvature, and the size is the usual turn-per-edge rule of curvature-adapted meshing.
/// \pre box.valid(), edge > 0, 0 < smallest <= edge. \throw what the surface throws (a budget's
/// LimitError); nothing else (points where f or its derivatives are not finite ask for nothing).
CurvatureFeatureSearch curvature_feature_sources(const Surface& surface, const Box& box, double edge,
                                                 double smallest, const CurvatureFeatureParams& params = {});

}  // namespace isopatch
