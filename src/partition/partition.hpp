#pragma once
/// \file partition.hpp
/// The octree partition of the projection mesher (docs/algorithms.md section 2). Uniform mode:
/// every surface leaf at one depth, no transitions between leaf sizes. Adaptive mode: leaves of
/// depths surface_depth..max_depth, 2:1 balanced, coarse leaves seeing their finer neighbours'
/// lattice points (transition faces, flat corners). Each surface leaf carries its
/// oriented loop(s) of edge crossings (the patch corners); crossings are shared by all the leaves
/// around their edge, so patches built on the loops assemble into a closed, oriented mesh.

#include "partition/cell_partition.hpp"
#include "partition/lattice.hpp"

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace isopatch {

static_assert(Lattice::kMaxDepth == kMaxPartitionLevel);

/// An octree cell: its depth and its coordinates at that depth (in cell sizes from the root's lower corner).
struct CellKey {
  int depth = 0;
  LatticePoint coords{};

  friend auto operator<=>(const CellKey&, const CellKey&) = default;
};

struct PartitionSettings {
  /// Depth of every surface leaf, 0..max_depth (0: the root cube is the only cell) (cells are 2^-depth of the
  /// root cube).
  int surface_depth = 5;
  /// Depth D of the finest lattice, surface_depth..20. Keys (segments, faces) are in its coordinates,
  /// so a later adaptive partition can refine to D while sharing them.
  int max_depth = 7;
  /// Points sampled strictly inside each cell edge by the edge test (docs/algorithms.md 2.9.1);
  /// 0 disables it.
  int edge_samples = 8;
  /// Half-angle of the normal-cone test in degrees (docs/algorithms.md 2.9.3), in (0, 90].
  double cone_angle_deg = 75.0;
  /// The in-plane gradient test on crossed faces (docs/algorithms.md 2.9.2).
  bool face_test = true;
  /// Use Surface::bound / gradient_bound when the surface offers them: sound pruning of empty cells
  /// and monotone edges certified without sampling.
  bool use_intervals = true;
  /// When set and true, build_partition stops with LimitError at the next cell.
  const std::atomic<bool>* cancel = nullptr;
  /// Adaptive mode (docs/algorithms.md 2.12): surface leaves start at surface_depth and are split down
  /// to max_depth while their topology is in doubt (several loops, an ambiguous (sub-)face, a segment
  /// crossed twice, an edge sample with the wrong sign, a loop against the gradients, a loop of fewer
  /// than 3 or more than 12 corners) or while they contain a cell of force_split; then 2:1 balanced
  /// across faces and edges. False: the uniform partition, exactly as before.
  bool adaptive = false;
  /// Adaptive mode only: cells to split (every leaf at depth <= key.depth containing the key's cell is
  /// split, so the key's cell ends up subdivided), e.g. leaves whose patch the mesher rejected. Keys
  /// with depth >= max_depth or outside the root are ignored.
  std::vector<CellKey> force_split;
};

/// One corner: the crossing of f = 0 with a crossed lattice segment. Its id is its index in
/// Partition::crossings; crossings are ordered by segment key, so ids do not depend on traversal.
struct Crossing {
  SegmentKey segment;  ///< the lattice segment (cell edge) it lies on
  Vec3 position = Vec3::Zero();
  Vec3 direction = Vec3::Zero();  ///< unit, from the negative end of the segment to the positive one
  Vec3 gradient = Vec3::Zero();   ///< grad f at position
};

/// A closed loop of corners. Side k runs from corners[k] to corners[k + 1 mod n] and lies on the cell
/// face side_faces[k]. Loops are counter-clockwise about the outward gradient (Newell normal . grad f
/// > 0 for simple leaves), so the neighbour across side_faces[k] traverses that side reversed.
struct Loop {
  std::vector<std::uint32_t> corners;  ///< indices into Partition::crossings, in loop order
  std::vector<FaceId> side_faces;
};

enum class LeafKind : std::uint8_t {
  Simple,   ///< passed every enabled test: one loop, presumably bounding one disk
  Complex,  ///< failed a test: holds any number of loops (possibly none); needs refinement or fallback
};

/// Adaptive mode: a leaf next to finer leaves (a "transition" leaf) has corners on the finer
/// segments of its edges and faces; a corner on a segment inside one of its faces is "flat". Side k of
/// a loop then lies on a quarter of the leaf's face: side_faces[k] is that quarter, i.e. the face of
/// the finer neighbour (the id both leaves compute). Crossings are always keyed by the finest segment.
struct Leaf {
  int depth = 0;
  LatticePoint coords{};  ///< cell coordinates at `depth` (in cell sizes from the root's lower corner)
  Box box;
  LeafKind kind = LeafKind::Complex;
  ComplexReason reason = ComplexReason::None;
  /// Corner-sign code, bit i set when corner i (core/cube_numbering.hpp) is negative. For a transition
  /// leaf (adaptive mode) informative only: its loops and verdict come from the boundary graph.
  std::uint8_t config = 0;
  std::vector<Loop> loops;
};

struct Partition {
  Lattice lattice;         ///< root cube and finest lattice (depth max_depth)
  int surface_depth = 0;   ///< depth of every leaf (adaptive mode: the coarsest leaf depth)
  double cell_size = 0.0;  ///< side of a leaf cell at surface_depth (adaptive: use Leaf::box per leaf)
  bool adaptive = false;   ///< built in adaptive mode
  std::vector<Crossing> crossings;
  std::vector<Leaf> leaves;  ///< surface leaves (Simple, or Complex with their loops), sorted by coords
  PartitionStats stats;
};

/// Builds the partition of `box` for `surface` (docs/algorithms.md 2.1-2.11).
///
/// A cell down to surface_depth is skipped as empty when bound() excludes 0 (sound) or, when the
/// surface gives no bound, when it passes the heuristic empty test: all 8 corners and the centre have
/// one sign and |f(centre)| > 2 * L * half-diagonal, with L the largest |grad f| at the corners and
/// the centre. This is a first-order Taylor bound with a safety factor 2 for the variation of the
/// gradient; it can miss closed components much smaller than the cell, as any sampling does. (The
/// gradient at the centre alone is not enough: it vanishes at critical points such as the
/// tanglecube's origin.) Other cells above surface_depth are split. A cell at surface_depth with equal
/// corner signs is empty unless an edge sample has the other sign (then it is a Complex leaf without
/// loops). A cell with mixed signs is a leaf: Simple when the configuration has one loop without
/// ambiguous faces and the edge, face, normal-cone and orientation tests pass, else Complex. After the
/// descent, cells around crossed edges that a wrong heuristic prune left out are visited directly, so
/// every crossed edge is surrounded by leaves and the loops form a closed surface.
///
/// Crossings are found once per lattice segment by the bracketed root finder (Illinois with bisection
/// safeguard, to 1e-13 of the edge), from the negative end. The result is deterministic: crossings
/// sorted by segment key, leaves by coordinates.
///
/// Adaptive mode (settings.adaptive): see PartitionSettings::adaptive and
/// build_adaptive_partition in adaptive_partition.hpp.
///
/// \throw InputError for settings out of range or an invalid box.
/// \throw EvaluationError when f or its gradient is NaN or infinite at a point the partition needs.
/// \throw LimitError when `settings.cancel` is raised.
Partition build_partition(const Surface& surface, const Box& box, const PartitionSettings& settings);

struct AdaptiveBuildMemo;  // adaptive_partition.hpp

/// The same, for adaptive settings, keeping the samples and crossings in `*memo` for the next call
/// (created on the first call; later calls must give the same surface, box, max_depth and edge_samples):
/// the same partition, fewer evaluations. The statistics count this call's evaluations only.
Partition build_partition(const Surface& surface, const Box& box, const PartitionSettings& settings,
                          std::unique_ptr<AdaptiveBuildMemo>& memo);

}  // namespace isopatch
