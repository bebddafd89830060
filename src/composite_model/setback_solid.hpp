#pragma once
/// \file setback_solid.hpp
/// A convex polyhedral solid with its edges rounded by rolling-ball blends and its vertices by setback
/// vertex blends (Varady & Rockwood, "Geometric construction for setback vertex blending", CAD 1997),
/// each vertex blend a 2n-sided I-patch (Varady, Benko, Kos & Rockwood 2001) where n edge blends meet:
/// sides alternate between an edge blend's cross-section arc (cut at the setback distance from the
/// vertex; ribbon the blend cylinder, bounding the setback plane) and a trimline on a face between two
/// springlines (ribbon the face plane; bounding the conic cylinder over the trimline, so the region is
/// concave, or in planar mode the plane over the chord). The result is closed: faces (planar, trimmed,
/// 2k sides for a k-gon), edge blends (cylinders, 4 sides) and vertex blends, G1 along every curve.

#include "composite_model/composite.hpp"
#include "composite_model/polyhedron_topology.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace isopatch {

struct SetbackSolid {
  std::string name;
  PolygonMesh mesh;      ///< a convex polyhedron, faces counter-clockwise from outside (or all clockwise)
  double radius = 0.0;   ///< blend radius of every edge, > 0
  double setback = 0.0;  ///< setback distance along every edge from every vertex, > 0
  bool conic_face_curves = true;  ///< smooth face trimlines (conic) or straight ones (planar)
  struct EdgeRadius {
    std::uint32_t a = 0, b = 0;  ///< 0-based vertices of the edge
    double radius = 0.0;
  };
  std::vector<EdgeRadius> edge_radii;  ///< overrides of `radius`
  struct VertexSetback {
    std::uint32_t vertex = 0;
    double setback = 0.0;
  };
  std::vector<VertexSetback> vertex_setbacks;  ///< overrides of `setback` for every edge at a vertex
};

/// Builds the rounded solid as a closed composite: patches "face k", "edge blend a-b" and
/// "vertex blend v" (1-based), curves shared by id. A vertex blend's rule A reference point (and, if
/// need be, weight factors) is the first best of a few candidates near the centroid of its 2n corners,
/// scored by measure_patch (patch_validity.hpp): see docs/ipatch.md.
/// \throw InputError on bad topology, a vertex with more than 8 edges or a face with more than 8
///        vertices (a vertex blend or a trimmed face has at most 16 sides), a non-planar face, a concave or
///        flat vertex or edge (mixed and concave vertices are not supported), radius or setback <= 0, a
///        setback too small for a face corner (the springlines meet beyond it) or too large for an edge (the
///        two ends' setbacks overlap), a setback too short for the blend radii at a vertex (a boundary
///        curve of its vertex blend runs outside another side's bound, measure_boundary_exit: the blend
///        could not reach it), or a reference point outside its region.
Composite build_setback_solid(const SetbackSolid& solid);

}  // namespace isopatch
