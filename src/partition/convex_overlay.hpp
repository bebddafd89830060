#pragma once
/// \file convex_overlay.hpp
/// The shared faces of a set of convex cells (convex_cell.hpp): every face of a cell is cut into the
/// pieces it shares with each neighbour on the other side of its plane (a face of a coarse cell may
/// meet several faces of finer ones), or kept whole where no cell lies beyond it (the region's
/// boundary). Piece vertices are numbered once for all cells (point_index.hpp), and every vertex of a
/// neighbouring piece that lies on a piece's edge is inserted into it, so the boundary of each cell is
/// a closed polygonal surface whose edges are shared, segment by segment, by all the cells around them:
/// crossings on those segments are the shared patch corners of Sipos & Salvi 2021, sec. 2.

#include <array>
#include <cstdint>
#include <vector>

#include "partition/convex_cell.hpp"
#include "partition/point_index.hpp"

namespace isopatch {

inline constexpr std::uint32_t kNoNeighbour = 0xffffffffu;

/// A planar piece of cell boundary shared by cells[0] and cells[1] (cells[0] < cells[1]; kNoNeighbour
/// on the region's boundary). Its vertices run counter-clockwise about `normal`, which points out of
/// cells[0].
struct OverlayPiece {
  std::array<std::uint32_t, 2> cells{kNoNeighbour, kNoNeighbour};
  Vec3 normal = Vec3::UnitX();
  int axis = -1;  ///< the axis of `normal` when it is exactly a coordinate axis (box and lattice planes)
  std::vector<std::uint32_t> vertices;  ///< ids into the point index
};

struct Overlay {
  std::vector<OverlayPiece> pieces;
  /// Per cell (only those asked for): its pieces, in face order.
  std::vector<std::vector<std::uint32_t>> cell_pieces;
};

/// The pieces of the cells flagged in `wanted`, against every cell of `cells`. The points of the
/// pieces are added to `points`.
/// \param strict  true for a partition given by a caller: a face covered only in part by neighbours
///                (a gap, or neighbours that do not meet face to face) and faces covered twice (an
///                overlap) raise InputError; false: a face partly covered is an internal error
/// \throw InputError as above (naming the cell and the face); Error(Internal) for inconsistent cells.
Overlay overlay_cells(const std::vector<ConvexCell>& cells, const std::vector<bool>& wanted,
                      PointIndex& points, bool strict);

/// The vertices of `polygon` (ids into `points`) with every known point that lies on one of its edges
/// (within the index's tolerance, strictly between the ends) inserted in order along the edge.
std::vector<std::uint32_t> with_edge_points(const std::vector<std::uint32_t>& polygon,
                                            const PointIndex& points);

}  // namespace isopatch
