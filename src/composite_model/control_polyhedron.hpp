#pragma once
/// \file control_polyhedron.hpp
/// A control polyhedron turned into a composite of I-patches, one n-sided patch per face, after Sipos,
/// Varady, Salvi & Vaitkus, "Multi-sided implicit surfacing with I-patches" (C&G 2020) as their public
/// code builds each side from corner points and normals ("bounding by normal"). Per edge (V, W), shared
/// by its two faces: the bounding plane through the chord and the mean vertex normal, the boundary conic
/// in it (tangent to both vertex tangent planes; circular by default), and the Liming ribbon whose trace
/// on the bounding plane is exactly that conic. Per face: the I-patch of its edges' ribbons and
/// bounding planes, through a reference point (rule A weights), with the vertex normals as corner
/// directions. The patches meet with G1 continuity along the curves and at the vertices.

#include "composite_model/composite.hpp"
#include "composite_model/polyhedron_topology.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace isopatch {

struct ControlPolyhedron {
  std::string name;
  PolygonMesh mesh;
  /// Per vertex (empty, or one entry per vertex): the unit normal; default the normalized sum of the
  /// adjacent faces' unit normals.
  std::vector<std::optional<Vec3>> normals;
  /// The shape of an edge's boundary conic: its weight (default cos(half the turning angle), a circular
  /// arc when the edge is symmetric), or a point the curve must pass through (inside the triangle of its
  /// end points and the tangent lines' intersection).
  struct EdgeShape {
    std::uint32_t a = 0, b = 0;  ///< 0-based vertices
    std::optional<double> weight;
    std::optional<Vec3> through;
  };
  std::vector<EdgeShape> edges;
  /// A face's reference point (default: the face centroid pushed out from the polyhedron's centroid to
  /// the mean distance of its corners; when the patch through it fails, because its ribbons differ in
  /// sign there or a line of measure_patch meets the patch twice, the first point on the face normal
  /// through the face centroid that passes, or the one that fails least) and weight factors d (default all 1;
  /// one per side).
  struct FaceShape {
    std::uint32_t face = 0;  ///< 0-based
    std::optional<Vec3> centre;
    std::vector<double> d;
  };
  std::vector<FaceShape> faces;
};

/// Builds the composite: curves (one per edge, from its lower-numbered vertex), patches (one per face,
/// named "face k", 1-based), each a closed I-patch with its bounding planes as region. Faces running
/// clockwise seen from outside (negative volume) are all reversed first.
/// \throw InputError on bad topology (find_topology_problem), a zero vertex normal, a normal parallel
///        to an edge, an edge whose normals ask for an S-shaped or reflex curve (no conic fits), an edge
///        option that names no edge or gives a weight <= 0 or a point outside the curve's triangle, a
///        reference point outside its face's region or where the ribbons differ in sign.
Composite build_control_polyhedron(const ControlPolyhedron& polyhedron);

}  // namespace isopatch
