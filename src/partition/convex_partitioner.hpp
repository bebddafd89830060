#pragma once
/// \file convex_partitioner.hpp
/// Partitions of general convex cells behind the mesher's Partitioner interface (cell_partition.hpp),
/// built by convex_partition.hpp. Two sources of cells:
/// - a lattice of cubes over the box (the octree's lattice, make_lattice) with every cube clipped by
///   the planes of a convex region: the surface is meshed inside the region, and where it leaves the
///   region its boundary lies on the region's planes (Sipos & Salvi 2021, sec. 2: "any convex
///   partitioning which is made of planar cuts");
/// - cells given by a caller (each a list of planes, within the box), checked for overlaps and gaps.
/// A rejected cell is split by three planes through the centre of its bounds, one per axis (a lattice
/// cube into its eight octants, then clipped again); its neighbours keep their faces, which then meet
/// several faces of the finer cells.

#include <isopatch/surface.hpp>

#include <atomic>
#include <cstdint>
#include <vector>

#include "partition/cell_partition.hpp"
#include "partition/convex_cell.hpp"
#include "partition/convex_partition.hpp"
#include "partition/lattice.hpp"

namespace isopatch {

struct ConvexPartitionerSettings {
  int start_level = 0;  ///< lattice: the cubes' starting depth; caller cells: splits at the start
  int max_level = 8;    ///< the deepest level a cell may reach, start_level..20
  int edge_samples = 8;
  double cone_angle_deg = 75.0;
  const std::atomic<bool>* cancel = nullptr;
};

class ConvexPartitioner final : public Partitioner {
 public:
  /// The lattice of `box` clipped by `region` (may be empty: the box alone).
  /// \throw InputError when the region leaves nothing of the box.
  static ConvexPartitioner clipped_lattice(const Surface& surface, const Box& box,
                                           std::vector<CellPlane> region,
                                           const ConvexPartitionerSettings& settings);
  /// The caller's cells, each the intersection of `box` with its planes.
  /// \throw InputError for a cell without volume (naming it), two cells that overlap, or faces that
  ///        neighbours cover only in part (a gap).
  static ConvexPartitioner given_cells(const Surface& surface, const Box& box,
                                       const std::vector<std::vector<CellPlane>>& cells,
                                       const ConvexPartitionerSettings& settings);

  CellPartition build() override;
  bool start_finer() override;
  void split(std::span<const std::size_t> cells) override;
  int max_level() const override { return settings_.max_level; }
  /// Pieces of general cells are never declared grazed: false.
  bool only_grazes_ambiguous_faces(std::size_t, const Sampler&) const override { return false; }

  /// The leaves as they stand (for tests).
  std::size_t leaf_count() const { return leaves_.size(); }

 private:
  struct Leaf {
    ConvexLeaf leaf;
    bool on_lattice = false;
    int depth = 0;
    LatticePoint coords{};
  };

  ConvexPartitioner(const Surface& surface, const Box& box, const ConvexPartitionerSettings& settings);
  void restart();
  void start_lattice();
  std::vector<Leaf> children(const Leaf& leaf) const;
  bool lattice_leaf(int depth, const LatticePoint& coords, Leaf& out) const;

  const Surface& surface_;
  Box box_;
  ConvexPartitionerSettings settings_;
  std::vector<CellPlane> region_;
  Lattice lattice_;
  bool lattice_mode_ = false;
  std::vector<ConvexLeaf> given_;
  std::vector<Leaf> leaves_;
  std::vector<std::size_t> last_cells_;  // leaf index of each cell of the last build
  std::vector<std::size_t> to_split_;
};

}  // namespace isopatch
