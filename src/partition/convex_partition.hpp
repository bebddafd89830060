#pragma once
/// \file convex_partition.hpp
/// A partition of general convex cells (convex_cell.hpp) as the projection mesher sees it
/// (cell_partition.hpp): Sipos & Salvi 2021, sec. 2, "any convex partitioning which is made of planar
/// cuts". The cells' shared faces come from convex_overlay.hpp; f is sampled once per vertex of the
/// overlay, crossings are found once per overlay segment (shared by every cell around it), each face
/// piece links its crossings by the sign rule (the negative vertices on the right of a side, seen
/// from outside), and the pieces' sides chain into loops. The single-sheet tests of
/// docs/algorithms.md 2.9 run on the general cells: several loops, ambiguous pieces (4 or more
/// crossings, resolved by the sign at the piece's centre), the edge test on every segment (certified
/// without samples where the gradient bound proves f monotone along it), the face test on every piece
/// with crossings (in-plane gradients at its vertices agree), the normal cone of the gradients at the
/// cell's vertices and corners, and the orientation of the loop against the gradients.

#include <isopatch/surface.hpp>

#include <atomic>
#include <vector>

#include "partition/cell_partition.hpp"
#include "partition/convex_cell.hpp"

namespace isopatch {

/// One cell of the partition and where it came from.
struct ConvexLeaf {
  ConvexCell cell;
  int level = 0;      ///< splits from the start
  double size = 0.0;  ///< its edge length before any clipping (> 0)
};

struct ConvexPartitionSettings {
  int edge_samples = 8;          ///< points inside each segment for the edge test, >= 0
  double cone_angle_deg = 75.0;  ///< normal-cone half-angle, (0, 90]
  /// Certify monotone segments by Surface::gradient_bound (no edge samples there) where it is offered.
  bool use_intervals = true;
  int start_level = 0;  ///< CellPartition::start_level
  /// A partition given by a caller: gaps and overlaps between faces are input errors.
  bool strict = false;
  const std::atomic<bool>* cancel = nullptr;
};

/// The partition of `leaves` for f = 0 of `surface` inside `region` (the bounds of all leaves). A leaf
/// holds the surface when the signs of f at its vertices differ; it is then a cell with its loops and
/// verdict, numbered in leaf order. A leaf whose vertices share a sign is left out (a feature that
/// crosses no segment of the overlay is not seen, as with any sampling).
/// `cell_leaves`, when given, receives the leaf of every cell.
/// \throw InputError (strict) for gaps and overlaps; EvaluationError when f is not finite at a sample;
///        LimitError when cancelled.
CellPartition build_convex_partition(const Surface& surface, const Box& region,
                                     const std::vector<ConvexLeaf>& leaves,
                                     const ConvexPartitionSettings& settings,
                                     std::vector<std::size_t>* cell_leaves = nullptr);

}  // namespace isopatch
