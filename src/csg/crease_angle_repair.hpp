#pragma once
/// \file crease_angle_repair.hpp
/// The last pass over a CSG shape's mesh: vertices of triangles with an angle under the floor are moved
/// towards the mean of their neighbours, each kept exactly on the functions it lies on: a vertex on one
/// face function (inside a piece, or on a seam, which only cuts a face) moves over that face; a vertex
/// on two (a crease) slides along the crease and is put back on both (surface/curve_point.hpp); a
/// vertex on three or more (a corner) stays. A move is kept only when it raises the smallest angle
/// around the vertex and turns no triangle against the faces' normals (angle-based smoothing as in
/// Zhou & Shimada 2000, "An angle-based approach to two-dimensional mesh smoothing", restricted to
/// the surface). The per-piece clean-up holds every piece's boundary; this pass frees seams and lets
/// crease vertices slide, which the triangles along piece boundaries need.

#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace isopatch {

/// What the pass did.
struct AngleRepair {
  std::size_t moved = 0;  ///< vertex moves kept
};

/// Moves vertices of triangles with an angle under `floor_degrees` (several sweeps, in vertex order: the
/// same result for any thread count). `faces` are the shape's face functions; a vertex lies on a face
/// when |f| / |grad f| <= `on_face` there; a moved vertex is put back on its faces to `tolerance`.
/// Positions change, topology does not. A vertex with `held` set (when given: one flag per vertex) stays
/// where it is (a block's seam vertices, which the block across must find where they were made).
/// A vertex on one face goes back onto it by surface/project_point.hpp's Newton steps.
/// \throw EvaluationError when a face function is not finite at a vertex; InputError when `held` does
///        not have one flag per vertex.
AngleRepair repair_small_angles(Mesh& mesh, const std::vector<SurfacePtr>& faces, double floor_degrees,
                                double on_face, double tolerance,
                                const std::vector<std::uint8_t>* held = nullptr);

}  // namespace isopatch
