#pragma once
/// \file face_regions.hpp
/// Cutting the faces of a CSG shape into disc-like pieces. The coarse mesh of the crease search tells
/// which boundary cycles bound the same connected part of a face (its vertices on that face, joined by
/// its edges): a part bounded by two or more cycles (a plate with a hole, the wall of a drilled hole), a
/// part bounded by none (a face with no crease), and a part whose normals turn by more than a set cone
/// are cut by a plane. The plane's seams are traced on the face like creases (curve_tracer.hpp) from
/// the points where the plane crosses the part's creases, which are split there; the coarse mesh's
/// edges across the plane are dropped, and the cycles walked again, until every part is one cycle.
/// docs/creases.md.

#include <vector>

#include "csg/crease_graph.hpp"
#include "csg/crease_search.hpp"
#include "csg/face_cycles.hpp"
#include "csg/face_set.hpp"

namespace isopatch {

/// Cuts the faces of `graph` until every part of a face is bounded by one cycle with normals within a
/// cone; returns the cycles.
/// \throw CreaseError when a part cannot be cut (no plane crosses it, a seam cannot be traced) or the
///        cuts do not end.
std::vector<FaceCycle> cut_into_discs(CreaseGraph& graph, FaceSet& faces, const ShapeSamples& samples,
                                      const Box& box);

}  // namespace isopatch
