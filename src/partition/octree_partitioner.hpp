#pragma once
/// \file octree_partitioner.hpp
/// The octree behind the cell-neutral Partitioner interface (cell_partition.hpp): the adaptive,
/// 2:1-balanced octree of build_partition (partition.hpp), seen as convex cells with shared corners and
/// faces. Depths are octree levels; splitting a cell halves it along every axis.

#include <isopatch/stage_settings.hpp>
#include <isopatch/surface.hpp>

#include <atomic>
#include <memory>

#include "partition/adaptive_partition.hpp"
#include "partition/cell_partition.hpp"
#include "partition/partition.hpp"

namespace isopatch {

/// How deep the octree starts and how deep it may refine.
struct OctreeDepthRequest {
  /// The wanted length of the starting cells, > 0.
  double cell_length = 1.0;
  /// True: the depth whose cells are closest to cell_length in log scale; false: the coarsest depth
  /// whose cells are at most cell_length.
  bool closest = false;
  int min_depth = 2;  ///< bounds of the starting depth, 0 <= min_depth <= max_depth <= kOctreeDepthLimit
  int max_depth = 8;  ///< the refinement limit, unless raised (below)
  /// When >= 0 and the wanted starting depth is max_depth or deeper, the limit becomes that depth plus
  /// raise_limit_by (at most kOctreeDepthLimit), so small features can still be refined. -1: keep
  /// max_depth.
  int raise_limit_by = -1;
  /// When > 0: the limit is also at least the coarsest depth whose cells are at most this long (at most
  /// kSizeFieldDepthLimit), for a size field that asks for small sizes somewhere (a thin rim).
  double finest_cell = 0.0;
};

/// How deep a size field's smallest size may take the octree: cells of 1/32768 of the box, below the
/// settings' limit (12), so that a rim 1/10000 of the box thin still gets cells smaller than its radius.
/// Only the few cells the field asks for go there.
inline constexpr int kSizeFieldDepthLimit = 15;

struct OctreeDepths {
  int start = 0;  ///< the starting depth, within [min_depth, limit]
  int limit = 0;  ///< the refinement limit
};

/// The starting depth and refinement limit of the octree over `box` (its root cube: make_lattice).
/// \throw InputError for an invalid box.
OctreeDepths plan_octree_depths(const Box& box, const OctreeDepthRequest& request);

/// The adaptive octree (PartitionSettings::adaptive) as a Partitioner. Owns nothing but its settings;
/// `surface` must outlive it.
class OctreePartitioner final : public Partitioner {
 public:
  /// \param settings  the octree's settings; surface_depth and max_depth give the start and the limit
  ///                  (adaptive is forced on)
  OctreePartitioner(const Surface& surface, const Box& box, PartitionSettings settings);

  CellPartition build() override;
  bool start_finer() override;
  void split(std::span<const std::size_t> cells) override;
  int max_level() const override { return settings_.max_depth; }
  bool only_grazes_ambiguous_faces(std::size_t cell, const Sampler& f) const override;

  /// The octree of the last build, for tests and diagnostics.
  const Partition& octree() const { return last_; }

 private:
  const Surface& surface_;
  Box box_;
  PartitionSettings settings_;
  Partition last_;
  /// The samples and crossings of the earlier builds (adaptive mode): a rebuild evaluates only what
  /// its new cells need.
  std::unique_ptr<AdaptiveBuildMemo> memo_;
};

/// The partition seen by the mesher: faces numbered by sorted face id, cells in leaf order, corners
/// in crossing order (both already deterministic).
CellPartition cell_partition_of(const Partition& octree);

/// The face's square as a (flat) box.
Box face_box(const Lattice& lattice, const FaceId& face);

}  // namespace isopatch
