#pragma once
/// \file crease_search.hpp
/// Finding every crease of a CSG shape in the box, certified by interval arithmetic. A Marching Cubes
/// mesh of f on a grid of about the target edge labels each of its vertices with the face active there
/// (face_set.hpp); every mesh edge whose ends lie on different faces seeds that pair: a seed is put on
/// f_i = f_j = 0 by Newton and the crease traced from it both ways (curve_tracer.hpp) to its corners or
/// round its loop. A seed whose Newton point is cut away by a third face (a face too narrow for the
/// grid, a chamfer) seeds the pairs with that face: narrow faces are found from their neighbours. Pairs
/// whose gradients agree along their meeting (the two sides of a smooth union's blend) are merged into
/// one face first. Last, the interval cover (crease_cover.hpp) bounds where two faces can meet at all;
/// each of its cells no traced crease passes is seeded at its centre, so creases the grid missed (a
/// feature smaller than a grid cell) are traced too, and cells nothing explains are counted.
/// docs/creases.md.

#include <isopatch/mesh.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "csg/crease_cover.hpp"
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

/// What the interval cover (crease_cover.hpp) certified: every crease in the box passes through its
/// finest cells, and each was explained by a traced crease, a crease traced from its centre, or a proof
/// that its faces cannot meet there; the rest are uncertain.
struct CreaseCertificate {
  std::size_t examined = 0;  ///< cells whose intervals were evaluated
  std::size_t cells = 0;     ///< finest cells where two faces may meet
  std::size_t found = 0;     ///< creases the grid's seeds missed, traced from those cells
  /// Cells where two faces lie on one another or touch without crossing (no crease: the shared face of
  /// two solids side by side, a face tangent to the shape at a point).
  std::size_t touching = 0;
  std::size_t uncertain = 0;  ///< cells no crease, seed or interval explained (creases may be missed there)
  Vec3 first_uncertain = Vec3::Zero();  ///< the centre of the first, when there is one
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
  CreaseCertificate certificate;
};

/// Finds the creases of f = 0 in `box` with a seed grid of about `cell` (clamped to 16..128 cells on
/// the longest side), then certifies the search by the interval cover (crease_cover.hpp): its cells
/// the grid's creases do not explain are seeded in turn. The graph's curves are creases, oriented with their
/// `left` face on the left seen from outside; their ends are nodes (a closed loop has one node at its start
/// and end). When a crease leaves the box the search stops and says where (`leaves_box`). \throw CreaseError
/// when a crease cannot be followed or its faces cannot be told apart; NoSurfaceError when f = 0 does not
/// cross the box; EvaluationError
///        for f not finite where evaluated.
/// `cover_budget`: cells the interval cover may examine (crease_cover()).
CreaseSearch find_creases(FaceSet& faces, const Box& box, double cell,
                          std::size_t cover_budget = kCoverBudget);

/// The tolerance every crease point is put on its functions to: |g| / |grad g| <= this share of the
/// box diagonal.
inline constexpr double kCreaseTolerance = 1e-13;

}  // namespace isopatch
