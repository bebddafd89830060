// Octree descent, leaf classification, shared crossings and loops (method.md 4.3, 4.4, 5.1, 5.2).
//
// Everything a neighbour must agree on is a function of shared lattice data: corner signs and face
// centres come from the half-lattice cache, crossings are keyed by segment, loop links by the face
// (cube_cycles.hpp). Only the Simple/Complex verdict is private to a cell, so it may use any sample.
#include "partition/partition.hpp"

#include "partition/adaptive_partition.hpp"
#include "partition/cell.hpp"
#include "partition/cell_checks.hpp"
#include "partition/cell_tests.hpp"
#include "partition/config_table.hpp"
#include "partition/cube_cycles.hpp"
#include "partition/index_map.hpp"
#include "partition/sample_cache.hpp"
#include "surface/bracketed_root.hpp"
#include "surface/sampler.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <unordered_set>

namespace isopatch {

const char* to_string(ComplexReason reason) {
  switch (reason) {
    case ComplexReason::None:
      return "none";
    case ComplexReason::SeveralLoops:
      return "several-loops";
    case ComplexReason::AmbiguousFace:
      return "ambiguous-face";
    case ComplexReason::EdgeTest:
      return "edge-test";
    case ComplexReason::FaceTest:
      return "face-test";
    case ComplexReason::NormalCone:
      return "normal-cone";
    case ComplexReason::Orientation:
      return "orientation";
  }
  return "unknown";
}

namespace {

constexpr int kMaxEdgeSamples = 1024;

void validate(const Box& box, const PartitionSettings& s) {
  if (!box.valid()) throw InputError("partition: the box must be finite with lo < hi on every axis");
  if (s.max_depth < 0 || s.max_depth > Lattice::kMaxDepth)
    throw InputError("partition: max_depth must be in 0.." + std::to_string(Lattice::kMaxDepth) + ", got " +
                     std::to_string(s.max_depth));
  if (s.surface_depth < 0 || s.surface_depth > s.max_depth)
    throw InputError("partition: surface_depth must be in 0..max_depth (" + std::to_string(s.max_depth) +
                     "), got " + std::to_string(s.surface_depth));
  if (s.edge_samples < 0 || s.edge_samples > kMaxEdgeSamples)
    throw InputError("partition: edge_samples must be in 0.." + std::to_string(kMaxEdgeSamples));
  if (!(s.cone_angle_deg > 0.0 && s.cone_angle_deg <= 90.0))
    throw InputError("partition: cone_angle_deg must be in (0, 90]");
}

class Builder {
 public:
  Builder(const Surface& surface, const PartitionSettings& settings, const Lattice& lattice)
      : surface_(surface),
        settings_(settings),
        lattice_(lattice),
        sampler_(surface),
        cache_(sampler_, lattice, settings.edge_samples),
        cos_cone_(std::cos(settings.cone_angle_deg * std::numbers::pi / 180.0)) {}

  Partition run();

 private:
  void visit(const Cell& cell);
  bool heuristically_empty(const Cell& cell, double corner_value);
  void surface_cell(const Cell& cell, const std::array<double, 8>& values, std::uint8_t negative);
  ComplexReason classify(const Cell& cell, const std::array<double, 8>& values, const ConfigEntry& config,
                         const std::vector<Loop>& loops, bool oriented);
  bool edge_test(const Cell& cell, const std::array<double, 8>& values);
  bool face_test(const Cell& cell, std::uint16_t crossed);
  bool cone_test(const Cell& cell, const std::vector<Loop>& loops);
  bool oriented_along_gradient(const Loop& loop) const;
  std::uint32_t crossing(const SegmentKey& key, double start_value, double end_value);
  void check_cancel() const;
  void close_holes();
  std::uint8_t corner_signs(const Cell& cell, std::array<double, 8>& values);
  Partition finish();

  const Surface& surface_;
  const PartitionSettings& settings_;
  Lattice lattice_;
  Sampler sampler_;
  SampleCache cache_;
  double cos_cone_;
  std::vector<Crossing> crossings_;
  IndexMap<SegmentKey, SegmentKeyHash> crossing_index_;  // same order as crossings_
  std::vector<Leaf> leaves_;
  PartitionStats stats_;
};

Partition Builder::run() {
  visit(Cell::make(lattice_, 0, {0, 0, 0}));
  close_holes();
  return finish();
}

// The heuristic empty test can prune a coarse cell whose corners share a sign while the surface
// crosses one of its finer edges; a leaf next to it then holds a crossing that not all of the 4 cells
// around its edge know. Visit those cells directly (flood fill along the crossings) so that every
// crossed edge is surrounded by leaves and the loops close up. Cells found this way have mixed corner
// signs, so they always become leaves.
void Builder::close_holes() {
  std::unordered_set<std::uint64_t> known;
  for (const Leaf& leaf : leaves_) known.insert(half_key(leaf.coords));
  const int depth = settings_.surface_depth;
  const std::uint32_t step = lattice_.step(depth);
  const std::uint32_t cells = 1u << depth;
  for (std::size_t c = 0; c < crossings_.size(); ++c) {  // grows while we iterate
    const CellsAroundSegment around = cells_around_segment(crossings_[c].segment);
    for (std::size_t k = 0; k < around.count; ++k) {
      const LatticePoint& p = around.points[k];
      const LatticePoint coords{p[0] / step, p[1] / step, p[2] / step};
      if (coords[0] >= cells || coords[1] >= cells || coords[2] >= cells ||
          !known.insert(half_key(coords)).second)
        continue;
      check_cancel();
      ++stats_.cells_recovered;
      if (!lattice_.inside(depth, coords)) continue;
      const Cell cell = Cell::make(lattice_, depth, coords);
      std::array<double, 8> values{};
      surface_cell(cell, values, corner_signs(cell, values));
    }
  }
}

std::uint8_t Builder::corner_signs(const Cell& cell, std::array<double, 8>& values) {
  std::uint8_t negative = 0;
  for (int i = 0; i < 8; ++i) {
    values[i] = cache_.value(cell.corner_half(i));
    if (is_negative(values[i])) negative = static_cast<std::uint8_t>(negative | (1u << i));
  }
  return negative;
}

void Builder::check_cancel() const {
  if (settings_.cancel && settings_.cancel->load(std::memory_order_relaxed)) throw LimitError("cancelled");
}

void Builder::visit(const Cell& cell) {
  check_cancel();
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
// half-diagonal and L the largest gradient norm at the centre and the corners. A gradient taken at the
// centre alone is not enough: at a critical point (the tanglecube's origin, grad f = 0) it would
// declare the whole root cell empty.
bool Builder::heuristically_empty(const Cell& cell, double corner_value) {
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

void Builder::surface_cell(const Cell& cell, const std::array<double, 8>& values, std::uint8_t negative) {
  const ConfigEntry& config = config_table()[negative];
  Leaf leaf;
  leaf.depth = cell.depth;
  leaf.coords = cell.coords;
  leaf.box = lattice_.cell_box(cell.depth, cell.coords);
  leaf.config = negative;

  if (config.kind == ConfigClass::Empty) {
    // Equal corner signs: empty unless an edge sample says otherwise (a feature smaller than the cell
    // that misses the corners; such a leaf has no loop but tells the caller to refine).
    if (settings_.edge_samples == 0 || edge_test(cell, values)) {
      ++stats_.empty_surface_cells;
      return;
    }
    leaf.kind = LeafKind::Complex;
    leaf.reason = ComplexReason::EdgeTest;
  } else {
    std::array<std::uint32_t, 12> corner_of_edge{};
    for (int e = 0; e < 12; ++e) {
      if (((config.crossed_edges >> e) & 1u) == 0) continue;
      const int lower = cube::edge_lower_corner(e);
      const int upper = cube::kEdge[e][0] == lower ? cube::kEdge[e][1] : cube::kEdge[e][0];
      corner_of_edge[e] = crossing(cell.edge(e), values[lower], values[upper]);
    }
    std::uint8_t centre_negative = 0;
    for (int f = 0; f < 6; ++f)
      if (face_ambiguous(negative, f) && is_negative(cache_.value(cell.face_centre_half(f))))
        centre_negative = static_cast<std::uint8_t>(centre_negative | (1u << f));

    bool oriented = true;
    for (const CubeCycle& cycle : cube_cycles(negative, centre_negative)) {
      Loop loop;
      for (std::size_t k = 0; k < cycle.edges.size(); ++k) {
        loop.corners.push_back(corner_of_edge[cycle.edges[k]]);
        loop.side_faces.push_back(cell.face(cycle.faces[k]));
      }
      if (!oriented_along_gradient(loop)) {
        oriented = false;
        ++stats_.orientation_disagreements;
      }
      leaf.loops.push_back(std::move(loop));
    }
    stats_.loops += leaf.loops.size();
    leaf.reason = classify(cell, values, config, leaf.loops, oriented);
    leaf.kind = leaf.reason == ComplexReason::None ? LeafKind::Simple : LeafKind::Complex;
  }
  if (leaf.kind == LeafKind::Simple) {
    ++stats_.simple_leaves;
  } else {
    ++stats_.complex_leaves;
    ++stats_.complex_by_reason[static_cast<std::size_t>(leaf.reason)];
    if (leaf.loops.empty()) ++stats_.leaves_without_loops;
  }
  leaves_.push_back(std::move(leaf));
}

ComplexReason Builder::classify(const Cell& cell, const std::array<double, 8>& values,
                                const ConfigEntry& config, const std::vector<Loop>& loops, bool oriented) {
  if (config.kind == ConfigClass::SeveralLoops) return ComplexReason::SeveralLoops;
  if (config.kind == ConfigClass::Ambiguous) return ComplexReason::AmbiguousFace;
  if (settings_.edge_samples > 0 && !edge_test(cell, values)) return ComplexReason::EdgeTest;
  if (settings_.face_test && !face_test(cell, config.crossed_edges)) return ComplexReason::FaceTest;
  if (!cone_test(cell, loops)) return ComplexReason::NormalCone;
  if (!oriented) return ComplexReason::Orientation;
  return ComplexReason::None;
}

// Edge test (method.md 4.3.2): a crossed edge changes sign exactly once along its samples, an uncrossed
// one never. An edge along an axis on which gradient_bound proves f monotone passes without samples.
bool Builder::edge_test(const Cell& cell, const std::array<double, 8>& values) {
  std::array<bool, 3> monotone{};
  if (settings_.use_intervals) {
    const auto bound = surface_.gradient_bound(lattice_.cell_box(cell.depth, cell.coords));
    if (bound) {
      ++stats_.interval_evaluations;
      for (int a = 0; a < 3; ++a)
        monotone[a] = !bound->gradient[a].empty() && !bound->gradient[a].contains_zero();
    }
  }
  for (int e = 0; e < 12; ++e) {
    if (monotone[cube::edge_axis(e)]) {
      ++stats_.edges_certified_by_interval;
      continue;
    }
    const int lower = cube::edge_lower_corner(e);
    const int upper = cube::kEdge[e][0] == lower ? cube::kEdge[e][1] : cube::kEdge[e][0];
    const std::span<const double> samples = cache_.segment_samples(cell.edge(e));
    const int expected = is_negative(values[lower]) != is_negative(values[upper]) ? 1 : 0;
    if (sign_changes(values[lower], samples, values[upper]) != expected) return false;
  }
  return true;
}

// Face test (method.md 4.3.3) on every face holding crossed edges: the in-plane gradients at the 4
// face corners and the face centre pairwise agree.
bool Builder::face_test(const Cell& cell, std::uint16_t crossed) {
  for (int f = 0; f < 6; ++f) {
    bool face_crossed = false;
    for (int e : cube::kFaceEdge[f]) face_crossed = face_crossed || ((crossed >> e) & 1u) != 0;
    if (face_crossed && !face_gradients_agree(cache_, cell, f)) return false;
  }
  return true;
}

// Normal-cone test (method.md 4.3.4): gradients at the corners, the centre, the face centres and the
// loop corners within the cone's half-angle of their mean direction.
bool Builder::cone_test(const Cell& cell, const std::vector<Loop>& loops) {
  return cell_gradients_within_cone(cache_, cell, loops, crossings_, cos_cone_);
}

// Method.md 5.2 step 5 as a check: the loops are already oriented by the signs (cube_cycles.hpp),
// which neighbours agree on by construction; here we only ask whether the geometry agrees.
bool Builder::oriented_along_gradient(const Loop& loop) const {
  return loop_oriented_along_gradient(loop, crossings_);
}

// Corner on a crossed segment (method.md 5.1), computed once per segment from its negative end A:
// phi(t) = f(A + t (B - A)) on [0, 1], Illinois with bisection safeguard, to 1e-13 in t.
std::uint32_t Builder::crossing(const SegmentKey& key, double start_value, double end_value) {
  if (const auto index = crossing_index_.find(key)) return *index;
  crossings_.push_back(segment_crossing(sampler_, lattice_, key, start_value, end_value,
                                        kSegmentRootTolerance, kSegmentRootIterations,
                                        stats_.root_evaluations));
  return crossing_index_.insert(key).first;
}

// Renumbers crossings by segment key and sorts leaves by coordinates, so the output does not depend
// on the order in which cells were visited.
Partition Builder::finish() {
  std::vector<std::uint32_t> order(crossings_.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t x, std::uint32_t y) { return crossings_[x].segment < crossings_[y].segment; });
  std::vector<std::uint32_t> new_id(crossings_.size());
  Partition p;
  p.crossings.reserve(crossings_.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) {
    new_id[order[k]] = k;
    p.crossings.push_back(crossings_[order[k]]);
  }
  for (Leaf& leaf : leaves_)
    for (Loop& loop : leaf.loops)
      for (std::uint32_t& c : loop.corners) c = new_id[c];
  std::sort(leaves_.begin(), leaves_.end(), [](const Leaf& x, const Leaf& y) {
    return std::tie(x.depth, x.coords) < std::tie(y.depth, y.coords);
  });
  p.lattice = lattice_;
  p.surface_depth = settings_.surface_depth;
  p.cell_size = lattice_.unit() * lattice_.step(settings_.surface_depth);
  p.leaves = std::move(leaves_);
  stats_.value_evaluations = sampler_.value_count();
  stats_.gradient_evaluations = sampler_.gradient_count();
  stats_.segment_sample_evaluations = cache_.segment_sample_evaluations();
  p.stats = stats_;
  return p;
}

}  // namespace

Partition build_partition(const Surface& surface, const Box& box, const PartitionSettings& settings) {
  validate(box, settings);
  if (settings.adaptive) return build_adaptive_partition(surface, box, settings);
  const Lattice lattice = make_lattice(box, settings.max_depth);
  return Builder(surface, settings, lattice).run();
}

}  // namespace isopatch
