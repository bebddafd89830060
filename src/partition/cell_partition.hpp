#pragma once
/// \file cell_partition.hpp
/// What the projection mesher needs of a partition of space, stated once and independent of how the
/// cells were made (Sipos & Salvi 2021, sec. 2: "any convex partitioning which is made of planar
/// cuts"). A partition is a set of convex cells that each hold the surface as one or more loops of
/// corners; corners are the crossings of f = 0 with cell edges, shared by every cell around their edge
/// through one id; each loop side lies on one cell face, named by an id shared by the two cells on
/// either side of it. Patches built on the loops therefore assemble into a closed, oriented mesh
/// without welding. The octree (octree_partitioner.hpp) implements it; a partition of general convex
/// cells is a second implementation of Partitioner. See docs/algorithms.md 2.9-2.10 for the tests behind the
/// verdicts.

#include <isopatch/geometry.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/cyclic.hpp"
#include "partition/convex_cell.hpp"
#include "partition/partition_stats.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

/// A crossing of f = 0 with a cell edge: a patch corner.
struct CellCorner {
  Vec3 position = Vec3::Zero();
  /// The edge direction from its negative end towards its positive one (not necessarily unit); lies in
  /// the plane of every face the edge bounds, so side points marched along blends of two corners'
  /// directions stay in their face.
  Vec3 direction = Vec3::Zero();
  Vec3 gradient = Vec3::Zero();  ///< grad f at position
};

/// No cell (CellFace::cells).
inline constexpr std::uint32_t kNoCell = 0xffffffffu;

/// A planar face of a cell (or the part of it that one neighbour shares) on which loop sides lie.
struct CellFace {
  Vec3 normal = Vec3::UnitX();  ///< unit normal of the face's plane
  /// The coordinate axis of `normal` (0..2) when the plane is axis-aligned, else -1: in-plane
  /// operations are then exact (a component set, not a projection with rounding).
  int axis = -1;
  Box region;  ///< bounds of the face: rays for side points stay inside it
  /// The cells whose loops have a side on this face, ascending: two where the face is shared by
  /// neighbours, one on the region's boundary; kNoCell where there is none.
  std::array<std::uint32_t, 2> cells{kNoCell, kNoCell};
};

/// v without its component along the face normal.
inline Vec3 in_plane(const CellFace& face, const Vec3& v) {
  if (face.axis >= 0) {
    Vec3 w = v;
    w[face.axis] = 0.0;
    return w;
  }
  return v - v.dot(face.normal) * face.normal;
}

/// p moved into the face's plane through `on_plane` (a point known to lie in it, such as a corner); for
/// an axis-aligned face the coordinate is copied, so the result lies in the plane exactly.
inline Vec3 onto_plane(const CellFace& face, const Vec3& p, const Vec3& on_plane) {
  if (face.axis >= 0) {
    Vec3 q = p;
    q[face.axis] = on_plane[face.axis];
    return q;
  }
  return p - (p - on_plane).dot(face.normal) * face.normal;
}

/// A closed loop of corners: side k runs from corners[k] to corners[next(k, n)] on face side_faces[k].
/// Loops are counter-clockwise about the outward gradient, so the cell across side_faces[k] traverses
/// that side reversed.
struct CellLoop {
  std::vector<std::uint32_t> corners;     ///< indices into CellPartition::corners
  std::vector<std::uint32_t> side_faces;  ///< indices into CellPartition::faces
};

/// Why a cell's single-sheet verdict failed: the first test it failed, in the order the tests run.
enum class ComplexReason : std::uint8_t {
  None,           ///< passed every test: one loop, presumably bounding one disk
  SeveralLoops,   ///< the corner signs give two or more loops
  AmbiguousFace,  ///< a face has 4 or more crossings (resolved by a face sample to make the loops)
  EdgeTest,       ///< an edge is crossed more than once (or, with equal end signs, at all)
  FaceTest,       ///< the in-plane gradients on a crossed face disagree
  NormalCone,     ///< the gradients do not fit in the normal cone
  Orientation,    ///< the loop's Newell normal opposes the gradients at its corners
};
static_assert(static_cast<int>(ComplexReason::Orientation) + 1 == kComplexReasonCount);

/// Short name of a reason ("edge-test", ...), for statistics.
const char* to_string(ComplexReason reason);

/// A convex cell holding the surface.
struct PartitionCell {
  Box bounds;         ///< bounds of the cell (clipped to the partition's region)
  double size = 0.0;  ///< the cell's edge length before clipping
  int level = 0;      ///< splits from the root: deeper cells are finer
  ComplexReason reason = ComplexReason::None;
  std::vector<CellLoop> loops;  ///< none when only an edge sample revealed the surface
  /// The planes of a general convex cell (outward normals): rays of its patch stay inside them. Empty
  /// for a cell that is its bounds (the octree's).
  std::vector<CellPlane> planes;
};

/// A partition as the mesher sees it. Deterministic: corners, faces and cells are numbered in an order
/// that depends on the cells only, never on the order of evaluation.
struct CellPartition {
  Box region;           ///< the region meshed: no cell or ray leaves it
  int start_level = 0;  ///< the level cells start at; deeper cells were refined
  std::vector<CellCorner> corners;
  std::vector<CellFace> faces;
  std::vector<PartitionCell> cells;
  PartitionStats stats;
};

/// A source of partitions that the mesher can ask to refine: the open set of partition kinds (octree,
/// convex cells) behind one interface.
class Partitioner {
 public:
  virtual ~Partitioner() = default;

  /// The partition as refined so far.
  /// \throw EvaluationError when f is not finite where needed; LimitError when cancelled.
  virtual CellPartition build() = 0;
  /// Restarts one level finer everywhere, forgetting the splits asked so far. False (nothing changes)
  /// when the start is already at the finest level.
  virtual bool start_finer() = 0;
  /// Asks that these cells of the last built partition be split before the next build (a cell at the
  /// finest level is left as it is).
  virtual void split(std::span<const std::size_t> cells) = 0;
  /// The finest level a cell may reach.
  virtual int max_level() const = 0;
  /// Whether f = 0 only grazes every ambiguous face of cell `cell` of the last build (lies within a small
  /// fraction of the cell of the face's plane, with grad f nearly along its normal): one sheet whose
  /// cut no refinement decides, not two sheets closer than the cell. Evaluates f through `f`.
  virtual bool only_grazes_ambiguous_faces(std::size_t cell, const Sampler& f) const = 0;
};

}  // namespace isopatch
