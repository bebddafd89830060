#pragma once
// The band of triangles between a trimmed face and its crease loops (zipped_face.hpp): each boundary loop
// of the trimmed face is walked with the crease point nearest to each of its vertices, joined to the
// crease arc it passes, and bridged across to another crease (or another part of the same one) where the
// nearest crease changes; the crease arcs no walk passed (the necks where two creases come closer than
// the trim's width) are joined crease to crease, across from the arcs facing them. Every crease edge
// must be used exactly once, else the join is refused.

#include <isopatch/mesh.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace isopatch {

/// Triangles joining the open chain `p` of ids into `x` (the band on its right) to the open chain `q` (the
/// band on its left) that starts beside p's first point, across the shorter diagonal each time.
void zip_chains(const std::vector<Vec3>& x, const std::vector<std::uint32_t>& p,
                const std::vector<std::uint32_t>& q, std::vector<Triangle>& out);

/// Triangles over the band between two chains with the same first and the same last vertex: `p` with the
/// band on its right, `q` with it on its left (a run of a trimmed face's boundary between two of its
/// vertices on the box, and the face's boundary on the box and the crease between them). Nothing when
/// both are the same edge.
void zip_between(const std::vector<Vec3>& x, const std::vector<std::uint32_t>& p,
                 const std::vector<std::uint32_t>& q, std::vector<Triangle>& out);

/// What to join: `positions` (holding the crease points), the crease loops as ids in the face's boundary
/// direction (the face on their left) and the trimmed face's boundary loops (the face on their left).
struct BandJoinInput {
  const std::vector<Vec3>& positions;
  const std::vector<std::vector<std::uint32_t>>& crease;
  const std::vector<std::vector<std::uint32_t>>& boundary;
  double edge = 0.0;  ///< the crease's spacing; a boundary vertex finds its crease within 3 of them
};

/// The joined band's triangles (along the face's orientation) and the crease loops no walk reached
/// (`untouched`, to be closed as strips or small faces by the caller), or nullopt with `failure` set
/// (a boundary vertex with no crease near, a neck between more than two arcs, a crease edge used twice).
struct BandJoin {
  std::vector<Triangle> triangles;
  std::vector<std::uint8_t> untouched;
  /// New points the triangles use after `positions` (a fan's centre in a neck where strips branch), not
  /// yet on the surface.
  std::vector<Vec3> extra;
};
std::optional<BandJoin> join_band(const BandJoinInput& in, std::string& failure);

}  // namespace isopatch
