#pragma once
/// \file cell.hpp
/// An octree cell as integer data: its depth, its coordinates at that depth, and the lattice names of
/// its corners, centres, edges and faces (cube numbering of core/cube_numbering.hpp).

#include "core/cube_numbering.hpp"
#include "partition/lattice.hpp"

namespace isopatch {

struct Cell {
  int depth = 0;
  LatticePoint coords{};   ///< in cell sizes at `depth`
  LatticePoint lo{};       ///< lower corner, finest coordinates
  std::uint32_t step = 0;  ///< side in finest steps

  static Cell make(const Lattice& lattice, int depth, const LatticePoint& coords) {
    const std::uint32_t s = lattice.step(depth);
    return Cell{depth, coords, {coords[0] * s, coords[1] * s, coords[2] * s}, s};
  }

  /// Child i (cube corner numbering) at depth + 1.
  Cell child(const Lattice& lattice, int i) const {
    const auto& o = cube::kCorner[i];
    return make(
        lattice, depth + 1,
        {2 * coords[0] + static_cast<std::uint32_t>(o[0]), 2 * coords[1] + static_cast<std::uint32_t>(o[1]),
         2 * coords[2] + static_cast<std::uint32_t>(o[2])});
  }

  /// Corner i, finest coordinates.
  LatticePoint corner(int i) const {
    LatticePoint p = lo;
    for (int a = 0; a < 3; ++a) p[a] += static_cast<std::uint32_t>(cube::kCorner[i][a]) * step;
    return p;
  }

  /// Corner i, half-lattice coordinates.
  LatticePoint corner_half(int i) const { return twice(corner(i)); }

  /// The cell centre, half-lattice coordinates.
  LatticePoint centre_half() const {
    const LatticePoint h = twice(lo);
    return {h[0] + step, h[1] + step, h[2] + step};
  }

  /// The centre of face f, half-lattice coordinates.
  LatticePoint face_centre_half(int f) const {
    LatticePoint h = centre_half();
    const int a = cube::kFaceAxis[f];
    h[a] = 2 * lo[a] + 2 * step * static_cast<std::uint32_t>(cube::kFaceSide[f]);
    return h;
  }

  /// Edge e as a lattice segment from its lower end.
  SegmentKey edge(int e) const {
    return SegmentKey{corner(cube::edge_lower_corner(e)), static_cast<std::uint32_t>(cube::edge_axis(e)),
                      step};
  }

  /// Face f as a lattice face id.
  FaceId face(int f) const {
    FaceId id{lo, static_cast<std::uint32_t>(cube::kFaceAxis[f]), step};
    id.lower[id.axis] += step * static_cast<std::uint32_t>(cube::kFaceSide[f]);
    return id;
  }

 private:
  static LatticePoint twice(const LatticePoint& p) { return {2 * p[0], 2 * p[1], 2 * p[2]}; }
};

}  // namespace isopatch
