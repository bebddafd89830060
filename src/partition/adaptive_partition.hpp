#pragma once
/// \file adaptive_partition.hpp
/// The adaptive partition (PartitionSettings::adaptive; docs/algorithms.md 2.12), called by
/// build_partition. Algorithm:
///  1. the descent shared with the uniform builder (octree_descent.hpp) gives the root cells, sampled
///     through the builder's one sample cache;
///  2. rounds until stable: 2:1 balance (faces and edges); analyse every leaf on its boundary graph;
///     add the surface_depth cell of any uncovered cell around a crossed segment (closure); split the
///     leaves below max_depth whose topology is in doubt or that contain a force_split cell;
///  3. output the leaves whose boundary graph is crossed (or fails the edge test).
///
/// Boundary graph of a leaf (2.12.2): an edge is split at its midpoint when a cell around it is split
/// (2:1 balance: by one level, so every segment is the edge of the finest leaf touching it); a face
/// whose neighbour is split becomes 4 quarter faces, each the face of one finer neighbour. Crossings
/// are computed per segment (shared by segment key with all leaves touching it), linked per (sub-)face
/// polygon (face_links.hpp) and walked into loops. The leaf's corner sign code alone is not used for
/// the verdict: a leaf is Simple when the graph gives one loop, no ambiguous (sub-)face, one sign
/// change per crossed segment and none on the others, and the face, cone and orientation tests pass.
/// A loop of fewer than 3 or more than 12 corners, an ambiguous polygon with more than 4 vertices, and
/// the reasons SeveralLoops, AmbiguousFace, EdgeTest and Orientation split the leaf below max_depth.
/// At max_depth leaves have no finer neighbours: their graph is the cube's and ambiguous faces are
/// resolved by the face centre as in the uniform mode, identically on both sides.

#include <cstdint>
#include <vector>

#include "partition/index_map.hpp"
#include "partition/partition.hpp"
#include "partition/sample_cache.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

/// What the adaptive builds of one surface, box, max_depth and edge_samples share: the samples of f on
/// the half lattice and the crossings of lattice segments, each a function of its point or segment
/// alone. A rebuild (more force_split cells, a finer surface_depth) then evaluates only what is new.
/// Not movable (the cache refers to the sampler); not thread-safe (one build at a time).
struct AdaptiveBuildMemo {
  AdaptiveBuildMemo(const Surface& surface, const Box& box, const PartitionSettings& settings);
  AdaptiveBuildMemo(const AdaptiveBuildMemo&) = delete;
  AdaptiveBuildMemo& operator=(const AdaptiveBuildMemo&) = delete;
  /// Whether a build of (box, settings) on `surface` may use this memo.
  bool fits(const Surface& surface, const Box& box, const PartitionSettings& settings) const;

  const Surface& surface;
  Box box;
  int max_depth;
  int edge_samples;
  Sampler sampler;  ///< counts every evaluation of every build
  SampleCache cache;
  std::vector<Crossing> crossings;
  IndexMap<SegmentKey, SegmentKeyHash> crossing_index;  ///< same order as crossings
};

/// \pre settings validated, settings.adaptive; memo (optional) fits the call. With a memo the
/// partition is the same as without; its statistics count only this build's new evaluations.
Partition build_adaptive_partition(const Surface& surface, const Box& box, const PartitionSettings& settings,
                                   AdaptiveBuildMemo* memo = nullptr);

}  // namespace isopatch
