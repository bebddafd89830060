#pragma once
/// \file cube_cycles.hpp
/// The purely combinatorial part of loop construction (docs/algorithms.md 2.8): from the signs at the
/// 8 corners of a cube, link the crossed edges face by face and walk the resulting cycles.

#include <cstdint>
#include <vector>

namespace isopatch {

/// One cycle of crossed cube edges.
struct CubeCycle {
  std::vector<int> edges;  ///< crossed edges in cycle order
  std::vector<int> faces;  ///< faces[k]: the face holding the side edges[k] -> edges[k + 1 mod n]
};

/// True when face f has four crossed edges (its two negative corners are diagonal).
/// \param negative  bit i set when corner i is negative (f < 0)
bool face_ambiguous(std::uint8_t negative, int face);

/// Mask of the crossed edges (bit e set when the ends of edge e have different signs).
std::uint16_t crossed_edges(std::uint8_t negative);

/// Links the crossed edges face by face and returns the cycles.
///
/// On a face with 2 crossed edges the two crossings are linked. On an ambiguous face (4 crossed edges)
/// bit f of `centre_negative` decides: when the face centre has the sign of the diagonal pair of
/// corners it is joined with, the other two corners are cut off; so two cells sharing the face, which
/// read the same centre sample, make the same links.
///
/// Orientation: every side is directed so that, seen from outside the cell, the negative corners of the
/// face lie on its right. This is the boundary orientation of the negative region of the cube's
/// surface, hence every crossed edge has exactly one incoming and one outgoing side, and two cells
/// sharing a face traverse each shared side in opposite directions (their outward normals are
/// opposite). For a loop around a negative region this is counter-clockwise about the outward
/// gradient, i.e. the orientation that docs/algorithms.md 2.9.4 checks, obtained from the signs alone.
///
/// Cycles are listed by their smallest edge, each starting at that edge: the result is a function of
/// the two masks only.
std::vector<CubeCycle> cube_cycles(std::uint8_t negative, std::uint8_t centre_negative);

}  // namespace isopatch
