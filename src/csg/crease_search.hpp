#pragma once
/// \file crease_search.hpp
/// Finding every crease of a CSG shape in the box. A Marching Cubes mesh of f on a grid of about the
/// target edge labels each of its vertices with the face active there (face_set.hpp); every mesh edge
/// whose ends lie on different faces seeds that pair: a seed is put on f_i = f_j = 0 by Newton and the
/// crease traced from it both ways (curve_tracer.hpp) to its corners or round its loop, so a crease is
/// found if a grid cell holds it. A seed whose Newton point is cut away by a third face (a face too
/// narrow for the grid, a chamfer) seeds the pairs with that face: narrow faces are found from their
/// neighbours. Pairs whose gradients agree along their meeting (the two sides of a smooth union's blend)
/// are merged into one face first. docs/creases.md.

#include <isopatch/mesh.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "csg/crease_graph.hpp"
#include "csg/face_set.hpp"

namespace isopatch {

/// The coarse mesh the search ran on, kept for the face analysis: its vertices on f = 0 and the
/// (merged) face of each.
struct ShapeSamples {
  Mesh mesh;
  std::vector<int> face;  ///< per vertex
  double cell = 0.0;      ///< grid spacing
};

/// The creases found.
struct CreaseSearch {
  CreaseGraph graph;
  ShapeSamples samples;
  std::size_t smooth_pairs = 0;  ///< pairs of faces merged (they meet without a crease)
  /// Pairs of faces that meet on the grid but whose meeting could not be traced as a curve (the faces
  /// touch tangentially: a sphere on a plane), and one point of each.
  std::vector<Vec3> tangential_contacts;
  /// Where a crease leaves the box, when one does (the search stops there).
  std::optional<Vec3> leaves_box;
};

/// Finds the creases of f = 0 in `box` with a seed grid of about `cell` (clamped to 16..128 cells on
/// the longest side). The graph's curves are creases, oriented with their `left` face on the left seen
/// from outside; their ends are nodes (a closed loop has one node at its start and end).
/// When a crease leaves the box the search stops and says where (`leaves_box`).
/// \throw CreaseError when a crease cannot be followed or its faces cannot be told apart; NoSurfaceError when
/// f = 0 does not cross the box; EvaluationError
///        for f not finite where evaluated.
CreaseSearch find_creases(FaceSet& faces, const Box& box, double cell);

/// The tolerance every crease point is put on its functions to: |g| / |grad g| <= this share of the
/// box diagonal.
inline constexpr double kCreaseTolerance = 1e-13;

}  // namespace isopatch
