#pragma once
/// \file cell_mesher.hpp
/// One pass of the projection mesher over one partition (Sipos & Salvi 2021, sec. 2): the boundary
/// vertices of every shared side (once per side, referenced by both patches), then a projected patch
/// per cell, assembled by vertex ids without welding. Each phase is a loop over independent items, so
/// it can run in parallel with the same output. Sees the partition only through cell_partition.hpp.

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/stage_settings.hpp>

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "ngon/base_surface.hpp"
#include "partition/cell_partition.hpp"
#include "projection/patch_projection.hpp"
#include "projection/side_points.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

/// What one pass did; rejections add up over the passes of a mesh, the rest is per pass.
struct CellMesherCounters {
  std::map<int, std::size_t> patches_by_sides;
  std::size_t rejected_patches = 0;
  std::map<PatchVerdict, std::size_t> rejected_by_verdict;
  std::size_t rejected_sides = 0;
  std::size_t fallback_cells = 0;
  std::size_t unprojected_vertices = 0;
  std::size_t refined_patches = 0;  ///< patches of cells deeper than the starting level
  PatchStats patch;

  /// Clears the per-pass counters, keeping the rejections.
  void start_pass();
};

/// The stage settings a pass reads.
struct CellMesherSettings {
  const PatchSettings& patch;
  const ProjectionSettings& projection;
  const BudgetSettings& budget;
};

/// Meshes one partition. A cell whose patch or one of whose sides is rejected is listed in to_split()
/// when it is shallower than `refinable_level` (the caller then refines it and meshes again); deeper
/// rejected cells, and cells whose topology is still in doubt, are closed by fans over their shared
/// boundaries.
class CellMesher {
 public:
  /// `resolution` > 0: every side gets that many segments; 0: each side gets its own count from the
  /// cells that share it and the target size at their corners (`size_at`; `uniform_sizes` when it is
  /// constant, see side_factor).
  CellMesher(const Sampler& f, const CellPartition& partition, CellMesherSettings settings, int resolution,
             int refinable_level, std::function<double(const Vec3&)> size_at, bool uniform_sizes);

  /// The mesh; meaningful only when to_split() is empty afterwards. Sides, then cells, run in parallel
  /// (TBB, in the caller's task arena) and are assembled in a fixed order: the same mesh for any number
  /// of threads. `size_at` and f are called concurrently. Adds "sides" and "patches" to `times`
  /// (may be null).
  /// \throw LimitError when cancelled or beyond BudgetSettings::max_vertices; EvaluationError as f does.
  Mesh run(CellMesherCounters& counters, StageTimes* times = nullptr);

  /// The role (role_value) of every vertex of the mesh run() returned.
  const std::vector<float>& roles() const { return roles_; }

  /// Smallest and largest segment count over the sides (0, 0 without sides).
  std::pair<int, int> segment_range() const;

  /// Cells to split before meshing again, ascending.
  std::vector<std::size_t> to_split() const { return {split_cells_.begin(), split_cells_.end()}; }

 private:
  /// Vertex ids at or above this, in a cell's output, are the cell's own new vertices (numbered from 0).
  static constexpr std::uint32_t kLocalVertex = 0x80000000u;

  /// What one cell adds (cells are meshed in parallel, then appended in order).
  struct CellOutput {
    std::vector<SurfacePoint> points;  ///< new vertices
    std::vector<float> roles;          ///< per new vertex
    std::vector<Triangle> triangles;   ///< ids: shared vertices, or kLocalVertex + new vertex
    PatchStats patch;
    std::optional<PatchVerdict> rejected;
    int patch_sides = 0;  ///< sides of the accepted patch, 0 without one
    bool refined = false;
    bool split = false;
    bool fan = false;
    std::size_t unprojected = 0;
  };

  /// A side shared by two loops: corner ids from < to, and the face it lies on.
  struct Side {
    std::uint32_t from = 0;
    std::uint32_t to = 0;
    std::uint32_t face = 0;
  };

  int segments(std::size_t s) const { return side_segments_[s]; }
  int cell_resolution(std::size_t c);
  int side_segments(std::size_t i);
  double side_factor(int level);
  double corner_size(std::uint32_t c) const;
  void collect_sides();
  bool refinable(std::size_t cell) const { return part_.cells[cell].level < refinable_level_; }
  std::size_t side_index(std::uint32_t a, std::uint32_t b) const;
  void compute_sides(CellMesherCounters& counters);
  SidePoints sample(std::size_t i, int segments);
  std::unique_ptr<BaseSurface> base_surface(const CellLoop& loop, std::vector<Vec3>& directions) const;
  /// The base of the settings, Automatic resolved (barycentric in cells).
  PatchSettings::Base base_kind() const {
    return settings_.patch.base == PatchSettings::Base::Automatic ? PatchSettings::Base::Barycentric
                                                                  : settings_.patch.base;
  }
  std::uint32_t side_vertex(std::uint32_t a, std::uint32_t b, int i) const;
  bool loop_sides_accepted(const CellLoop& loop) const;
  void mesh_cells(CellMesherCounters& counters);
  void append(std::size_t c, const CellOutput& out, CellMesherCounters& counters);
  void mesh_cell(std::size_t c, CellOutput& out) const;
  PatchVerdict mesh_patch(const PartitionCell& cell, const CellLoop& loop, CellOutput& out) const;
  void mesh_fan(const PartitionCell& cell, const CellLoop& loop, CellOutput& out) const;
  void add_vertex(const Vec3& position, const Vec3& gradient, float role);

  const Sampler& f_;
  const CellPartition& part_;
  CellMesherSettings settings_;
  ProjectionParams params_;
  int fixed_resolution_;
  int refinable_level_;
  std::function<double(const Vec3&)> size_at_;
  bool uniform_sizes_;                     // size_at_ is constant (see side_factor)
  std::vector<double> corner_sizes_;       // target size at each corner (automatic resolution only)
  std::vector<int> cell_resolutions_;      // per cell, 0 until asked
  std::vector<double> side_factors_;       // per level, 0 until asked (see side_factor)
  std::vector<int> side_segments_;         // per side, in key order
  std::vector<std::size_t> side_offsets_;  // per side, the mesh id of its first inner point
  std::vector<Side> sides_;
  std::vector<std::vector<std::size_t>> side_cells_;  // per side, the cells whose loops use it
  std::set<std::size_t> split_cells_;
  std::vector<std::vector<Vec3>> side_curves_;  // Coons base: dense face curve per side, in key order
  std::vector<bool> side_accepted_;
  std::vector<Vec3> gradients_;  // per mesh vertex
  std::vector<float> roles_;     // per mesh vertex, see ProjectionSettings::vertex_roles
  Mesh mesh_;
};

}  // namespace isopatch
