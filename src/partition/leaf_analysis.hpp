#pragma once
/// \file leaf_analysis.hpp
/// The analysis of one leaf of the adaptive octree (docs/algorithms.md 2.12): its corner signs, the
/// boundary graph of its faces (split where a neighbour is finer), the edge test on every segment, the
/// links of the crossings into loops, and the single-sheet tests (2.9) that decide whether it is simple
/// or must be split. A LeafAnalyser reads the shared build state without changing it (the sample cache,
/// the crossings found so far, the tree) and keeps what it evaluates itself, so several analysers may
/// run at once, one per task; the builder then merges their findings in a fixed order.

#include <isopatch/surface.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include "partition/cell.hpp"
#include "partition/index_map.hpp"
#include "partition/leaf_tree.hpp"
#include "partition/partition.hpp"
#include "partition/sample_cache.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

/// What the analysis of one leaf found.
struct LeafAnalysis {
  Leaf leaf;                        ///< its loops' corners index the analyser's crossings()
  std::vector<SegmentKey> crossed;  ///< crossed segments of the boundary graph
  bool output = false;              ///< crossed, or an edge sample has the wrong sign
  bool split = false;               ///< wants splitting (ignoring max_depth and force_split)
  bool flat = false;                ///< a crossing lies inside one of the leaf's faces
};

/// The shared, read-only state of one round of analyses. Nothing in it may change while an analyser
/// that was given it lives.
struct LeafAnalysisInputs {
  const Surface& surface;
  const PartitionSettings& settings;
  const Lattice& lattice;
  const LeafTree& tree;
  const Sampler& sampler;
  double cos_cone = 1.0;                                       ///< cos of settings.cone_angle_deg
  const SampleCache& cache;                                    ///< samples evaluated so far
  const std::vector<Crossing>& crossings;                      ///< crossings found so far
  const IndexMap<SegmentKey, SegmentKeyHash>& crossing_index;  ///< their segments, same order
};

class LeafAnalyser {
 public:
  explicit LeafAnalyser(const LeafAnalysisInputs& in) : in_(in), cache_(SampleCache::overlay(in.cache)) {}

  /// Analyses the leaf `key` of in.tree (docs/algorithms.md 2.12.2): the same result whichever
  /// analyser runs it and whatever it analysed before. \throw EvaluationError when f is not finite at
  /// a sample; LimitError when settings.cancel is raised.
  LeafAnalysis analyse(const CellKey& key);

  /// The crossings the analyses so far use, in the order they first met them (those of in.crossings
  /// copied); LeafAnalysis::leaf loop corners index this list.
  const std::vector<Crossing>& crossings() const { return crossings_; }
  /// The samples this analyser holds (an overlay of in.cache: SampleCache::merge_into).
  const SampleCache& cache() const { return cache_; }
  /// Its counts: interval_evaluations, edges_certified_by_interval, root_evaluations.
  const PartitionStats& stats() const { return stats_; }

 private:
  struct Polygon {                       // one (sub-)face polygon of a leaf's boundary graph
    std::vector<LatticePoint> vertices;  // finest coordinates, counter-clockwise from outside
    FaceId face;
  };
  std::vector<Polygon> boundary_polygons(const CellKey& key, const Cell& cell) const;
  bool segment_passes(const SegmentKey& key, const std::array<bool, 3>& monotone);
  std::array<bool, 3> monotone_axes(const Cell& cell);
  ComplexReason classify(const Cell& cell, const LeafAnalysis& a, bool ambiguous, bool edge_ok,
                         const std::array<bool, 6>& face_crossed);
  bool face_test(const Cell& cell, const std::array<bool, 6>& face_crossed);
  bool cone_test(const Cell& cell, const std::vector<Loop>& loops);
  bool oriented_along_gradient(const Loop& loop) const;
  std::uint32_t crossing(const SegmentKey& key);

  const LeafAnalysisInputs& in_;
  SampleCache cache_;
  std::vector<Crossing> crossings_;
  IndexMap<SegmentKey, SegmentKeyHash> crossing_index_;  // same order as crossings_
  PartitionStats stats_;
};

}  // namespace isopatch
