#pragma once
/// \file partition.hpp
/// The octree partition of the projection mesher (method.md sections 4 and 5.1-5.3). Uniform mode:
/// every surface leaf at one depth, no transitions between leaf sizes. Adaptive mode: leaves of
/// depths surface_depth..max_depth, 2:1 balanced, coarse leaves seeing their finer neighbours'
/// lattice points (transition faces, flat corners). Each surface leaf carries its
/// oriented loop(s) of edge crossings (the patch corners); crossings are shared by all the leaves
/// around their edge, so patches built on the loops assemble into a closed, oriented mesh.

#include "partition/lattice.hpp"

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

namespace isopatch {

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
  /// Points sampled strictly inside each cell edge by the edge test (method.md 4.3.2); 0 disables it.
  int edge_samples = 8;
  /// Half-angle of the normal-cone test in degrees (method.md 4.3.4), in (0, 90].
  double cone_angle_deg = 75.0;
  /// The in-plane gradient test on crossed faces (method.md 4.3.3).
  bool face_test = true;
  /// Use Surface::bound / gradient_bound when the surface offers them: sound pruning of empty cells
  /// and monotone edges certified without sampling.
  bool use_intervals = true;
  /// When set and true, build_partition stops with LimitError at the next cell.
  const std::atomic<bool>* cancel = nullptr;
  /// Adaptive mode (method.md 4.4, 4.5, 5.3): surface leaves start at surface_depth and are split down
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

/// The first test a Complex leaf failed, in the order the tests run.
enum class ComplexReason : std::uint8_t {
  None,           ///< the leaf is Simple
  SeveralLoops,   ///< the corner signs give two loops (two triangles at opposite corners)
  AmbiguousFace,  ///< a face has 4 crossings (resolved by its centre sample to make the loops)
  EdgeTest,       ///< an edge is crossed more than once (or, with equal corner signs, at all)
  FaceTest,       ///< the in-plane gradients on a crossed face disagree
  NormalCone,     ///< the gradients do not fit in the normal cone
  Orientation,    ///< the loop's Newell normal opposes the gradients at its corners
};
inline constexpr int kComplexReasonCount = 7;

/// Short name of a reason ("edge-test", ...), for statistics.
const char* to_string(ComplexReason reason);

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
  /// Corner-sign code, bit i set when corner i (cube.hpp) is negative. For a transition leaf
  /// (adaptive mode) informative only: its loops and verdict come from the boundary graph.
  std::uint8_t config = 0;
  std::vector<Loop> loops;
};

struct PartitionStats {
  std::uint64_t cells_visited = 0;
  std::uint64_t pruned_by_interval = 0;   ///< cells skipped because bound() excludes 0 (sound)
  std::uint64_t pruned_by_heuristic = 0;  ///< cells skipped by the first-order empty test (heuristic)
  std::uint64_t empty_surface_cells = 0;  ///< cells at surface depth with equal signs everywhere sampled
  std::uint64_t cells_recovered = 0;      ///< leaves found next to crossings after a wrong heuristic prune
  std::uint64_t simple_leaves = 0;
  std::uint64_t complex_leaves = 0;
  std::array<std::uint64_t, kComplexReasonCount> complex_by_reason{};  ///< indexed by ComplexReason
  std::uint64_t leaves_without_loops = 0;  ///< Complex: equal corner signs, an edge sample of the other sign
  std::uint64_t loops = 0;
  std::uint64_t orientation_disagreements = 0;    ///< loops of any leaf whose Newell normal opposes grad f
  std::uint64_t edges_certified_by_interval = 0;  ///< edge tests settled by gradient_bound
  std::uint64_t value_evaluations = 0;            ///< all evaluations of f alone, including the two below
  std::uint64_t segment_sample_evaluations = 0;   ///< of which for the edge test
  std::uint64_t root_evaluations = 0;             ///< of which inside the root finder
  std::uint64_t gradient_evaluations = 0;         ///< evaluations of f with its gradient
  std::uint64_t interval_evaluations = 0;         ///< calls of bound() and gradient_bound()
  // Filled in adaptive mode only (the descent counters above then come from the initial uniform
  // descent; the evaluation counters add up both passes).
  std::array<std::uint64_t, Lattice::kMaxDepth + 1> leaves_per_depth{};  ///< output leaves by depth
  std::uint64_t leaves_with_flat_corners = 0;  ///< leaves with a corner inside one of their faces
  std::uint64_t max_loop_size = 0;             ///< most corners of any loop
  std::uint64_t adaptive_rounds = 0;           ///< analyse / split rounds until stable
  std::uint64_t forced_splits = 0;             ///< leaves split because of force_split
  std::uint64_t topology_splits = 0;           ///< leaves split because their topology was in doubt
  std::uint64_t balance_splits = 0;            ///< leaves split to restore 2:1 balance
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

/// Builds the partition of `box` for `surface` (method.md 4.1-4.4, 5.1, 5.2).
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

}  // namespace isopatch
