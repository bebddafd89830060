#pragma once
/// \file face_links.hpp
/// Linking the crossings on the boundary polygon of one (sub-)face (docs/algorithms.md 2.8, 2.12.2).
/// The polygon is the face's boundary as a leaf sees it: its corners and, on a transition face, the
/// lattice points of finer neighbours on its edges, counter-clockwise seen from outside the leaf.

#include <span>
#include <vector>

namespace isopatch {

/// A directed side between two crossed segments of the polygon (segment k joins vertex k to k + 1).
struct FaceSide {
  int from = 0;
  int to = 0;
};

struct FaceLinks {
  std::vector<FaceSide> sides;
  bool ambiguous = false;   ///< 4 or more crossed segments
  bool unresolved = false;  ///< ambiguous with more than 4 vertices: no sides were made
};

/// Links the crossed segments of a polygon with vertex signs `negative` (segment k is crossed when
/// vertices k and k + 1 differ). Two crossed segments are linked; four on a 4-vertex polygon are
/// linked by the centre sample as in cube_cycles.hpp (the centre joins the diagonal pair of its sign),
/// so the two leaves sharing the face, which see the same polygon reversed and the same centre, make
/// the same links. Sides are directed with the negative vertices on their right seen from outside,
/// so the other leaf traverses each side in the opposite direction.
FaceLinks link_face(std::span<const bool> negative, bool centre_negative);

}  // namespace isopatch
