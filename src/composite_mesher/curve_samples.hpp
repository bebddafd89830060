#pragma once
/// \file curve_samples.hpp
/// Points on the composite's boundary arcs (composite.hpp) at equal arc length: the one sampling of a
/// curve that both patches using it share (Sipos & Salvi 2021, sec. 2: boundary vertices computed once
/// and referenced by both patches, so the mesh is watertight without welding), and the dense polylines
/// the multi-sided C0 Coons base is built over (Salvi 2020; patch/coons_patch.hpp).

#include <isopatch/geometry.hpp>

#include <cstddef>
#include <vector>

#include "composite_model/composite.hpp"

namespace isopatch {

/// The arc's length, from a table of 512 chords (relative error below 1e-6 for the arcs of a
/// construction, which turn by less than 180 degrees).
/// \throw InputError when the arc is not finite, its weight is not positive, or its length is 0.
double arc_length(const ConicArc& arc);

/// segments + 1 points from arc.start to arc.end (exactly those at the ends), at equal arc length up
/// to the table's resolution. Every point is the arc evaluated at a parameter, so it lies on the
/// conic (and on the functions of the patches whose side it is) to rounding.
/// \pre segments >= 1. \throw InputError as arc_length().
std::vector<Vec3> sample_arc(const ConicArc& arc, int segments);

/// Whether curve i of the composite is a traced curve (Composite::traced). \throw InputError as
/// curve_length() for a malformed traced curve.
bool is_traced(const Composite& c, std::size_t i);

/// The length of curve i of the composite: its traced polyline's when it is traced, else its arc's.
/// \throw InputError as arc_length(), or for a traced curve of fewer than 2 finite points or length 0.
double curve_length(const Composite& c, std::size_t i);

/// segments + 1 points on curve i from its start to its end: sample_arc() of its arc, or for a traced
/// curve points at equal arc length along its polyline, each put back on both of its functions
/// (surface/curve_point.hpp; the ends are the polyline's ends exactly).
/// \throw InputError as curve_length(); EvaluationError when a sample cannot be put back on both
///        functions (the polyline is too coarse for the curve, or the functions touch there).
std::vector<Vec3> sample_curve(const Composite& c, std::size_t i, int segments);

/// The samples of a side: sample_arc() of its curve, in the side's direction.
std::vector<Vec3> side_samples(const ConicArc& arc, bool reversed, int segments);

}  // namespace isopatch
