#pragma once
/// \file composite.hpp
/// A composite implicit surface: patches, each the zero set of its own function inside its own region,
/// that meet along boundary curves known from their construction (Sipos & Salvi 2021, sec. 4: "corner
/// points and boundary curves ... known in advance"; Varady, Benko, Kos & Rockwood 2001 for I-patches;
/// Varady & Rockwood 1997 for setback vertex blends). This is the one description that the builders
/// (a control polyhedron, setback vertex blends; ipatch/*) produce and that the meshers (projection with
/// the curves as the Coons boundary, Marching Cubes on the piecewise function) consume.
///
/// Conventions, which every producer guarantees and every consumer may rely on:
/// - every function is negative inside the solid and positive outside;
/// - a patch's region is { x : b(x) >= 0 for every b in bounds };
/// - a patch's sides run counter-clockwise seen from outside the solid: side k ends where side k+1
///   starts (cyclically), exactly (the same Vec3), so the patches close up by curve id;
/// - a curve is used by exactly two patch sides in opposite directions when the composite is closed
///   (once when it bounds an open composite);
/// - curves lie on the functions of the patches that use them (|f| / |grad f| tiny there).

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace isopatch {

/// A rational quadratic Bezier arc (start, control, end; weight): a conic, or a straight segment when
/// the control point lies on the chord (weight 1 and control at the midpoint give uniform speed).
struct ConicArc {
  Vec3 start = Vec3::Zero();
  Vec3 control = Vec3::Zero();
  Vec3 end = Vec3::Zero();
  double weight = 1.0;  ///< > 0; cos(half the turning angle) for a circular arc

  /// The point at t in [0, 1] (clamped); exactly `start` at t = 0 and exactly `end` at t = 1.
  Vec3 point(double t) const;
};

/// A curve known as the meeting of two smooth functions (a crease or a seam of a CSG shape, src/csg):
/// a dense polyline on it from its start to its end, and the two functions. The mesher samples it by
/// arc length along the polyline and puts every sample back on both functions (surface/curve_point.hpp).
struct TracedCurve {
  std::vector<Vec3> points;  ///< >= 2 points on first = second = 0; front() and back() are its ends
  SurfacePtr first;          ///< one function the curve lies on
  SurfacePtr second;         ///< the other
};

/// One side of a patch: a curve of the composite, traversed from its start to its end or reversed.
struct PatchSide {
  std::uint32_t curve = 0;  ///< index into Composite::curves
  bool reversed = false;    ///< true: the side runs from the curve's end to its start
};

/// One patch: its own implicit function, its boundary as curves, its projection directions at the
/// corners and the region of space that holds it.
struct CompositePatch {
  std::string name;  ///< for errors and statistics: "face 3", "edge blend 0-1", "vertex blend 2"
  SurfacePtr surface;
  std::vector<PatchSide> sides;  ///< n >= 3 sides; corner k is where side k starts
  /// Unit projection directions at the corners (corner k = start of side k), pointing out of the solid.
  std::vector<Vec3> corner_directions;
  /// The region's bounding functions: the patch lies where every one is >= 0. Planes and the quadrics
  /// the construction needs; possibly curved, so the region may be concave.
  std::vector<SurfacePtr> bounds;
};

/// A composite surface: shared curves and the patches bounded by them.
struct Composite {
  std::string name;
  Box box;  ///< bounds of the solid, grown by a margin: the box meshers and renderers use
  std::vector<ConicArc> curves;
  /// Empty, or one per curve: a curve whose entry has points is that traced curve (its arc then holds
  /// the same ends and is not read for the curve's shape).
  std::vector<TracedCurve> traced;
  std::vector<CompositePatch> patches;
};

/// Where `side` of a patch starts and ends (the curve's ends, swapped when the side is reversed).
/// \pre side.curve < c.curves.size().
Vec3 side_start(const Composite& c, const PatchSide& side);
Vec3 side_end(const Composite& c, const PatchSide& side);

}  // namespace isopatch
