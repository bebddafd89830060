#pragma once
// A tile's cut made of its faces' curves (tiles.hpp): the curves joined into loops, and a tile's mesh
// joined to them in place of its own cut.

#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>
#include <isopatch/tiles.hpp>

#include <span>
#include <vector>

namespace isopatch::blocks {

/// The loops of a tile's cut: the curves of its six faces, joined where they meet on the tile's edges
/// (an end of a curve on one face is the same double as an end of a curve on the face across that
/// edge), each loop without its first point repeated. Loops in the order of their first curve.
/// \throw LimitError ("tiles") when an end is shared by other than two curves (a curve through a corner
///        of the tile).
std::vector<std::vector<Vec3>> tile_loops(std::span<const FaceCurves> faces);

/// `mesh` (a mesh of `surface` in the tile, oriented along grad f, its cut on the tile's faces) with its
/// cut replaced by `loops`: the triangles with a corner on the cut removed (and more where the rest would
/// not have simple boundary loops), every boundary loop left joined to the loop of points nearest to it
/// by a strip (each step the shorter diagonal), and every loop with no part of the mesh beside it closed
/// by a fan around a point put on f = 0. The points of `loops` are the result's boundary, bit for bit,
/// after the kept vertices of `mesh`.
/// \param edge  the base edge length (the loops' spacing)
/// \throw LimitError ("tiles") when a boundary loop of the mesh lies near no loop, or two of them near one
///        (curves closer than about two base edges); EvaluationError where f is not finite.
Mesh join_to_loops(const Mesh& mesh, const Surface& surface, const std::vector<std::vector<Vec3>>& loops,
                   double edge);

}  // namespace isopatch::blocks
