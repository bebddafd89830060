// The octree descent shared by both builders (octree_descent.hpp).
#include "partition/octree_descent.hpp"

#include <isopatch/error.hpp>

#include <cmath>
#include <optional>
#include <unordered_set>

#include "core/cube_numbering.hpp"
#include "partition/cell_tests.hpp"
#include "surface/sign_rule.hpp"

namespace isopatch {
namespace {

class Descent {
 public:
  Descent(const Surface& surface, const Lattice& lattice, const PartitionSettings& settings,
          SampleCache& cache, PartitionStats& stats)
      : surface_(surface), lattice_(lattice), settings_(settings), cache_(cache), stats_(stats) {}

  std::vector<SurfaceCell> run() {
    visit(Cell::make(lattice_, 0, {0, 0, 0}));
    close_holes();
    return std::move(cells_);
  }

 private:
  void visit(const Cell& cell);
  bool heuristically_empty(const Cell& cell, double corner_value);
  void surface_cell(const Cell& cell, const std::array<double, 8>& values, std::uint8_t negative);
  std::uint8_t corner_signs(const Cell& cell, std::array<double, 8>& values);
  void close_holes();

  const Surface& surface_;
  const Lattice& lattice_;
  const PartitionSettings& settings_;
  SampleCache& cache_;
  PartitionStats& stats_;
  std::vector<SurfaceCell> cells_;
};

std::uint8_t Descent::corner_signs(const Cell& cell, std::array<double, 8>& values) {
  std::uint8_t negative = 0;
  for (int i = 0; i < 8; ++i) {
    values[i] = cache_.value(cell.corner_half(i));
    if (is_negative(values[i])) negative = static_cast<std::uint8_t>(negative | (1u << i));
  }
  return negative;
}

void Descent::visit(const Cell& cell) {
  check_partition_cancel(settings_);
  if (!lattice_.inside(cell.depth, cell.coords)) return;  // outside the box
  ++stats_.cells_visited;
  bool bounded = false;
  if (settings_.use_intervals) {
    const std::optional<Interval> bound = surface_.bound(lattice_.cell_box(cell.depth, cell.coords));
    if (bound) ++stats_.interval_evaluations;
    if (bound && !bound->empty()) {
      bounded = true;
      if (!bound->contains_zero()) {
        ++stats_.pruned_by_interval;
        return;
      }
    }
  }
  std::array<double, 8> values{};
  const std::uint8_t negative = corner_signs(cell, values);
  if (!bounded && (negative == 0 || negative == 0xff) && heuristically_empty(cell, values[0])) {
    ++stats_.pruned_by_heuristic;
    return;
  }
  if (cell.depth < settings_.surface_depth) {
    for (int i = 0; i < 8; ++i) visit(cell.child(lattice_, i));
    return;
  }
  surface_cell(cell, values, negative);
}

// First-order emptiness test for a cell whose corners share one sign: |f(c)| > 2 L h, with h the
// half-diagonal and L the largest gradient norm at the centre and the corners.
bool Descent::heuristically_empty(const Cell& cell, double corner_value) {
  const LatticePoint centre = cell.centre_half();
  const double fc = cache_.value(centre);
  if (is_negative(fc) != is_negative(corner_value)) return false;
  const double half_diagonal = 0.5 * std::sqrt(3.0) * lattice_.unit() * cell.step;
  const double limit = std::abs(fc) / (2.0 * half_diagonal);  // empty iff every |grad f| sampled < limit
  if (!(cache_.gradient(centre).norm() < limit)) return false;
  for (int i = 0; i < 8; ++i)
    if (!(cache_.gradient(cell.corner_half(i)).norm() < limit)) return false;
  return true;
}

void Descent::surface_cell(const Cell& cell, const std::array<double, 8>& values, std::uint8_t negative) {
  // Equal corner signs: empty unless an edge sample says otherwise (a feature smaller than the cell
  // that misses the corners).
  if ((negative == 0 || negative == 0xff) &&
      (settings_.edge_samples == 0 ||
       cell_edges_pass(surface_, lattice_, settings_, cache_, cell, values, stats_))) {
    ++stats_.empty_surface_cells;
    return;
  }
  cells_.push_back(SurfaceCell{cell, values, negative});
}

// The heuristic empty test can prune a coarse cell whose corners share a sign while the surface
// crosses one of its finer edges; a cell next to it then holds a crossing that not all of the 4 cells
// around its edge know. Visit those cells directly (flood fill along the crossed edges) so that every
// crossed edge is surrounded by cells and the loops close up. Cells found this way have mixed corner
// signs (the crossed edge is one of theirs), so they are always kept.
void Descent::close_holes() {
  std::unordered_set<std::uint64_t> known;
  for (const SurfaceCell& c : cells_) known.insert(half_key(c.cell.coords));
  const int depth = settings_.surface_depth;
  const std::uint32_t step = lattice_.step(depth);
  const std::uint32_t count = 1u << depth;
  for (std::size_t i = 0; i < cells_.size(); ++i) {  // grows while we iterate
    for (int e = 0; e < 12; ++e) {
      const SurfaceCell& c = cells_[i];
      const int lower = cube::edge_lower_corner(e);
      const int upper = cube::kEdge[e][0] == lower ? cube::kEdge[e][1] : cube::kEdge[e][0];
      if (((c.negative >> lower) & 1u) == ((c.negative >> upper) & 1u)) continue;
      const CellsAroundSegment around = cells_around_segment(c.cell.edge(e));
      for (std::size_t k = 0; k < around.count; ++k) {
        const LatticePoint& p = around.points[k];
        const LatticePoint coords{p[0] / step, p[1] / step, p[2] / step};
        if (coords[0] >= count || coords[1] >= count || coords[2] >= count ||
            !known.insert(half_key(coords)).second)
          continue;
        check_partition_cancel(settings_);
        ++stats_.cells_recovered;
        if (!lattice_.inside(depth, coords)) continue;
        const Cell cell = Cell::make(lattice_, depth, coords);
        std::array<double, 8> values{};
        surface_cell(cell, values, corner_signs(cell, values));
      }
    }
  }
}

}  // namespace

std::vector<SurfaceCell> descend_to_surface_cells(const Surface& surface, const Lattice& lattice,
                                                  const PartitionSettings& settings, SampleCache& cache,
                                                  PartitionStats& stats) {
  return Descent(surface, lattice, settings, cache, stats).run();
}

void check_partition_cancel(const PartitionSettings& settings) {
  if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) throw LimitError("cancelled");
}

bool cell_edges_pass(const Surface& surface, const Lattice& lattice, const PartitionSettings& settings,
                     SampleCache& cache, const Cell& cell, const std::array<double, 8>& values,
                     PartitionStats& stats) {
  std::array<bool, 3> monotone{};
  if (settings.use_intervals) {
    const auto bound = surface.gradient_bound(lattice.cell_box(cell.depth, cell.coords));
    if (bound) {
      ++stats.interval_evaluations;
      for (int a = 0; a < 3; ++a)
        monotone[a] = !bound->gradient[a].empty() && !bound->gradient[a].contains_zero();
    }
  }
  for (int e = 0; e < 12; ++e) {
    if (monotone[cube::edge_axis(e)]) {
      ++stats.edges_certified_by_interval;
      continue;
    }
    const int lower = cube::edge_lower_corner(e);
    const int upper = cube::kEdge[e][0] == lower ? cube::kEdge[e][1] : cube::kEdge[e][0];
    const std::span<const double> samples = cache.segment_samples(cell.edge(e));
    const int expected = is_negative(values[lower]) != is_negative(values[upper]) ? 1 : 0;
    if (sign_changes(values[lower], samples, values[upper]) != expected) return false;
  }
  return true;
}

}  // namespace isopatch
