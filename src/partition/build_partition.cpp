// The uniform octree builder: classification of the cells the shared descent (octree_descent.hpp)
// yields, shared crossings and loops (docs/algorithms.md 2.4-2.10).
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
#include "partition/octree_descent.hpp"
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
  void surface_cell(const Cell& cell, const std::array<double, 8>& values, std::uint8_t negative);
  ComplexReason classify(const Cell& cell, const std::array<double, 8>& values, const ConfigEntry& config,
                         const std::vector<Loop>& loops, bool oriented);
  bool face_test(const Cell& cell, std::uint16_t crossed);
  bool cone_test(const Cell& cell, const std::vector<Loop>& loops);
  bool oriented_along_gradient(const Loop& loop) const;
  std::uint32_t crossing(const SegmentKey& key, double start_value, double end_value);
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
  for (const SurfaceCell& c : descend_to_surface_cells(surface_, lattice_, settings_, cache_, stats_))
    surface_cell(c.cell, c.values, c.negative);
  return finish();
}

void Builder::surface_cell(const Cell& cell, const std::array<double, 8>& values, std::uint8_t negative) {
  const ConfigEntry& config = config_table()[negative];
  Leaf leaf;
  leaf.depth = cell.depth;
  leaf.coords = cell.coords;
  leaf.box = lattice_.cell_box(cell.depth, cell.coords);
  leaf.config = negative;

  if (config.kind == ConfigClass::Empty) {
    // Equal corner signs, yet an edge sample has the other sign (the descent keeps no other such cell):
    // a feature smaller than the cell that misses the corners; no loop, but the caller must refine.
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
  if (settings_.edge_samples > 0 &&
      !cell_edges_pass(surface_, lattice_, settings_, cache_, cell, values, stats_))
    return ComplexReason::EdgeTest;
  if (settings_.face_test && !face_test(cell, config.crossed_edges)) return ComplexReason::FaceTest;
  if (!cone_test(cell, loops)) return ComplexReason::NormalCone;
  if (!oriented) return ComplexReason::Orientation;
  return ComplexReason::None;
}

// Face test (docs/algorithms.md 2.9.2) on every face holding crossed edges: the in-plane gradients at the 4
// face corners and the face centre pairwise agree.
bool Builder::face_test(const Cell& cell, std::uint16_t crossed) {
  for (int f = 0; f < 6; ++f) {
    bool face_crossed = false;
    for (int e : cube::kFaceEdge[f]) face_crossed = face_crossed || ((crossed >> e) & 1u) != 0;
    if (face_crossed && !face_gradients_agree(cache_, cell, f)) return false;
  }
  return true;
}

// Normal-cone test (docs/algorithms.md 2.9.3): gradients at the corners, the centre, the face centres and the
// loop corners within the cone's half-angle of their mean direction.
bool Builder::cone_test(const Cell& cell, const std::vector<Loop>& loops) {
  return cell_gradients_within_cone(cache_, cell, loops, crossings_, cos_cone_);
}

// The orientation check of docs/algorithms.md 2.9.4: the loops are already oriented by the signs
// (cube_cycles.hpp), which neighbours agree on by construction; here we only ask whether the geometry
// agrees.
bool Builder::oriented_along_gradient(const Loop& loop) const {
  return loop_oriented_along_gradient(loop, crossings_);
}

// Corner on a crossed segment (docs/algorithms.md 2.7), computed once per segment from its negative end A:
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

Partition build_partition(const Surface& surface, const Box& box, const PartitionSettings& settings,
                          std::unique_ptr<AdaptiveBuildMemo>& memo) {
  validate(box, settings);
  if (!settings.adaptive) throw Error(ErrorKind::Internal, "partition: a memo is for adaptive builds");
  if (!memo) memo = std::make_unique<AdaptiveBuildMemo>(surface, box, settings);
  return build_adaptive_partition(surface, box, settings, memo.get());
}

Partition build_partition(const Surface& surface, const Box& box, const PartitionSettings& settings) {
  validate(box, settings);
  if (settings.adaptive) return build_adaptive_partition(surface, box, settings);
  const Lattice lattice = make_lattice(box, settings.max_depth);
  return Builder(surface, settings, lattice).run();
}

}  // namespace isopatch
