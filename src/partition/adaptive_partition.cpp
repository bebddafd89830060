// Adaptive partition: rounds of balance / analyse / split on a LeafTree until stable
// (adaptive_partition.hpp). Everything two leaves must agree on is a function of shared lattice data:
// segment and face splits come from the tree (symmetric), signs and (sub-)face centres from the
// half-lattice cache, crossings from the segment key, links from the polygon (face_links.hpp).
#include "partition/adaptive_partition.hpp"

#include "partition/cell.hpp"
#include "partition/cell_checks.hpp"
#include "partition/cell_tests.hpp"
#include "partition/face_links.hpp"
#include "partition/index_map.hpp"
#include "partition/leaf_analysis.hpp"
#include "partition/leaf_tree.hpp"
#include "partition/octree_descent.hpp"
#include "partition/sample_cache.hpp"
#include "surface/bracketed_root.hpp"
#include "surface/sampler.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <numbers>
#include <numeric>
#include <optional>
#include <span>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace isopatch {

namespace {

/// Leaves per task of analyse_in_tasks: fixed, so that the tasks (and the evaluations they repeat) do
/// not depend on the number of threads; large enough that few samples are shared between tasks.
constexpr std::size_t kLeavesPerTask = 64;
/// Tasks run at once before their results are merged (and the next ones read them): bounds the
/// overlays' memory to that many tasks' samples.
constexpr std::size_t kTasksPerWave = 16;

/// The Z-order (Morton 1966) key of a cell's lower corner at the finest depth: tasks of consecutive
/// leaves in this order are compact blocks of space, so they share few samples with other tasks.
std::uint64_t z_order(const CellKey& key, int finest) {
  std::uint64_t z = 0;
  const int up = finest - key.depth;
  for (int bit = Lattice::kMaxDepth - 1; bit >= 0; --bit)
    for (int a = 0; a < 3; ++a)
      z = (z << 1) | (((static_cast<std::uint64_t>(key.coords[a]) << up) >> bit) & 1u);
  return z;
}

class AdaptiveBuilder {
 public:
  AdaptiveBuilder(const Surface& surface, const PartitionSettings& settings, AdaptiveBuildMemo& memo)
      : surface_(surface),
        settings_(settings),
        lattice_(memo.cache.lattice()),
        sampler_(memo.sampler),
        cache_(memo.cache),
        cos_cone_(std::cos(settings.cone_angle_deg * std::numbers::pi / 180.0)),
        tree_(settings.surface_depth, settings.max_depth),
        crossings_(memo.crossings),
        crossing_index_(memo.crossing_index),
        values_before_(memo.sampler.value_count()),
        gradients_before_(memo.sampler.gradient_count()),
        segment_samples_before_(memo.cache.segment_sample_evaluations()) {}

  Partition run();

 private:
  bool close(const LeafAnalysis& a);
  void check_cancel() const;
  std::vector<LeafAnalysis> analyse_in_tasks(const std::vector<CellKey>& keys);
  Partition finish(std::vector<LeafAnalysis>& analyses);

  const Surface& surface_;
  const PartitionSettings& settings_;
  const Lattice& lattice_;
  const Sampler& sampler_;
  SampleCache& cache_;  // the memo's, shared with earlier and later builds
  double cos_cone_;
  LeafTree tree_;
  std::unordered_set<CellKey, CellKeyHash> forced_;  // force_split cells and their ancestors
  std::vector<Crossing>& crossings_;
  IndexMap<SegmentKey, SegmentKeyHash>& crossing_index_;                     // same order as crossings_
  std::uint64_t values_before_, gradients_before_, segment_samples_before_;  // the memo's counts at the start
  PartitionStats stats_;
};

void AdaptiveBuilder::check_cancel() const {
  check_partition_cancel(settings_);
}

Partition AdaptiveBuilder::run() {
  // The roots: the cells of the plain descent to surface_depth, sampled through the builder's cache.
  for (const SurfaceCell& root : descend_to_surface_cells(surface_, lattice_, settings_, cache_, stats_))
    tree_.add_root(root.cell.coords);
  const int s = settings_.surface_depth;
  for (const CellKey& key : settings_.force_split) {
    if (key.depth < s || key.depth >= settings_.max_depth) continue;
    for (int d = s; d <= key.depth; ++d) {
      const int up = key.depth - d;
      forced_.insert(CellKey{d, {key.coords[0] >> up, key.coords[1] >> up, key.coords[2] >> up}});
    }
  }
  // A leaf's analysis depends on the tree only through whether its same-size face and edge neighbours
  // are split, so it is kept until one of them (or the leaf) is split.
  std::unordered_map<CellKey, LeafAnalysis, CellKeyHash> known;
  auto split = [&](const CellKey& key) {
    known.erase(key);
    for (const auto& o : face_edge_offsets()) {
      LatticePoint n = key.coords;
      for (int a = 0; a < 3; ++a) n[a] += static_cast<std::uint32_t>(o[a]);
      known.erase(CellKey{key.depth, n});
    }
  };
  std::vector<LeafAnalysis> analyses;
  for (;;) {
    check_cancel();
    ++stats_.adaptive_rounds;
    const std::vector<CellKey> balanced = tree_.balance();
    stats_.balance_splits += balanced.size();
    for (const CellKey& key : balanced) split(key);
    analyses.clear();
    std::vector<CellKey> to_split;
    bool changed = false;
    // The leaves that need an analysis are analysed first, in tasks that only read the build's state
    // (an analysis does not depend on close(): a new root is never split); then, in leaf order, their
    // results are used as one loop over the leaves used them before.
    const std::vector<CellKey> leaves = tree_.leaves();
    std::vector<CellKey> pending;
    for (const CellKey& key : leaves)
      if (!(key.depth < settings_.max_depth && forced_.count(key)) && !known.count(key))
        pending.push_back(key);
    std::vector<LeafAnalysis> fresh = analyse_in_tasks(pending);
    std::size_t next_fresh = 0;
    for (const CellKey& key : leaves) {
      check_cancel();
      if (key.depth < settings_.max_depth && forced_.count(key)) {
        ++stats_.forced_splits;
        to_split.push_back(key);
        continue;
      }
      auto it = known.find(key);
      if (it == known.end()) {
        it = known.emplace(key, std::move(fresh[next_fresh++])).first;
        changed = close(it->second) || changed;
      }
      if (key.depth < settings_.max_depth && it->second.split) {
        ++stats_.topology_splits;
        to_split.push_back(key);
        continue;
      }
      if (it->second.output) analyses.push_back(it->second);
    }
    for (const CellKey& key : to_split) {
      tree_.split(key);
      split(key);
    }
    if (!changed && to_split.empty()) break;
  }
  return finish(analyses);
}

// Closure: every cell around a crossed segment must be covered by the tree (the 4 leaves around an
// edge all see its crossing); an uncovered one gets its surface_depth cell as a new root.
bool AdaptiveBuilder::close(const LeafAnalysis& a) {
  const int finest = settings_.max_depth;
  const int up = finest - settings_.surface_depth;
  bool added = false;
  for (const SegmentKey& key : a.crossed) {
    const CellsAroundSegment around = cells_around_segment(key);
    for (std::size_t k = 0; k < around.count; ++k) {
      const LatticePoint& p = around.points[k];
      if (tree_.locate(finest, p).where != LeafTree::Where::Outside) continue;
      added = tree_.add_root({p[0] >> up, p[1] >> up, p[2] >> up}) || added;
    }
  }
  return added;
}

// The analyses of `keys` (in that order) by tasks of kLeavesPerTask leaves consecutive in Z-order (an
// analysis does not depend on which leaves were analysed before it), kTasksPerWave tasks at once; after
// each wave its tasks' samples, crossings and counts are merged in task order (the next wave reads them)
// and their loops renumbered into crossings_. Tasks and waves are fixed by the list alone, so are the
// evaluations they make (a point two tasks of one wave need is evaluated by both): the same partition
// and the same counts for any number of threads. The first task's error is the one raised.
std::vector<LeafAnalysis> AdaptiveBuilder::analyse_in_tasks(const std::vector<CellKey>& keys) {
  const std::size_t tasks = (keys.size() + kLeavesPerTask - 1) / kLeavesPerTask;
  const LeafAnalysisInputs inputs{surface_,  settings_, lattice_,   tree_,          sampler_,
                                  cos_cone_, cache_,    crossings_, crossing_index_};
  std::vector<LeafAnalysis> out(keys.size());
  std::vector<std::pair<std::uint64_t, std::uint32_t>> order(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i)
    order[i] = {z_order(keys[i], settings_.max_depth), static_cast<std::uint32_t>(i)};
  std::sort(order.begin(), order.end());
  const auto leaves_of = [&](std::size_t task) {
    return std::pair{task * kLeavesPerTask, std::min(keys.size(), (task + 1) * kLeavesPerTask)};
  };
  std::vector<std::uint32_t> shared;
  for (std::size_t wave = 0; wave < tasks; wave += kTasksPerWave) {
    const std::size_t wave_end = std::min(tasks, wave + kTasksPerWave);
    std::vector<std::optional<LeafAnalyser>> analysers(wave_end - wave);
    std::vector<std::exception_ptr> errors(wave_end - wave);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(wave, wave_end, 1), [&](const auto& range) {
      for (std::size_t task = range.begin(); task != range.end(); ++task) {
        try {
          LeafAnalyser& analyser = analysers[task - wave].emplace(inputs);
          for (auto [i, end] = leaves_of(task); i < end; ++i)
            out[order[i].second] = analyser.analyse(keys[order[i].second]);
        } catch (...) {
          errors[task - wave] = std::current_exception();
        }
      }
    });
    for (const std::exception_ptr& error : errors)
      if (error) std::rethrow_exception(error);
    for (std::size_t task = wave; task < wave_end; ++task) {
      const LeafAnalyser& analyser = *analysers[task - wave];
      shared.clear();
      for (const Crossing& c : analyser.crossings()) {
        const auto [index, inserted] = crossing_index_.insert(c.segment);
        if (inserted) crossings_.push_back(c);
        shared.push_back(index);
      }
      for (auto [i, end] = leaves_of(task); i < end; ++i)
        for (Loop& loop : out[order[i].second].leaf.loops)
          for (std::uint32_t& c : loop.corners) c = shared[c];
      analyser.cache().merge_into(cache_);
      stats_.interval_evaluations += analyser.stats().interval_evaluations;
      stats_.edges_certified_by_interval += analyser.stats().edges_certified_by_interval;
      stats_.root_evaluations += analyser.stats().root_evaluations;
      analysers[task - wave].reset();  // merged: no second copy while the rest merge
    }
  }
  return out;
}

// Keeps the crossings the loops use, renumbered by segment key; leaves sorted by (depth, coords).
Partition AdaptiveBuilder::finish(std::vector<LeafAnalysis>& analyses) {
  std::vector<std::uint32_t> used;
  for (const LeafAnalysis& a : analyses)
    for (const Loop& loop : a.leaf.loops) used.insert(used.end(), loop.corners.begin(), loop.corners.end());
  std::sort(used.begin(), used.end(),
            [&](std::uint32_t x, std::uint32_t y) { return crossings_[x].segment < crossings_[y].segment; });
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<std::uint32_t> new_id(crossings_.size());
  Partition p;
  for (std::uint32_t k = 0; k < used.size(); ++k) {
    new_id[used[k]] = k;
    p.crossings.push_back(crossings_[used[k]]);
  }
  PartitionStats& s = stats_;
  for (LeafAnalysis& a : analyses) {
    Leaf& leaf = a.leaf;
    for (Loop& loop : leaf.loops) {
      s.max_loop_size = std::max<std::uint64_t>(s.max_loop_size, loop.corners.size());
      if (!loop_oriented_along_gradient(loop, crossings_)) ++s.orientation_disagreements;
      for (std::uint32_t& c : loop.corners) c = new_id[c];
    }
    s.loops += leaf.loops.size();
    ++s.leaves_per_depth[static_cast<std::size_t>(leaf.depth)];
    if (a.flat) ++s.leaves_with_flat_corners;
    if (leaf.kind == LeafKind::Simple) {
      ++s.simple_leaves;
    } else {
      ++s.complex_leaves;
      ++s.complex_by_reason[static_cast<std::size_t>(leaf.reason)];
      if (leaf.loops.empty()) ++s.leaves_without_loops;
    }
    p.leaves.push_back(std::move(leaf));
  }
  std::sort(p.leaves.begin(), p.leaves.end(), [](const Leaf& x, const Leaf& y) {
    return std::tie(x.depth, x.coords) < std::tie(y.depth, y.coords);
  });
  p.lattice = lattice_;
  p.surface_depth = settings_.surface_depth;
  p.cell_size = lattice_.unit() * lattice_.step(settings_.surface_depth);
  p.adaptive = true;
  s.value_evaluations = sampler_.value_count() - values_before_;
  s.gradient_evaluations = sampler_.gradient_count() - gradients_before_;
  s.segment_sample_evaluations = cache_.segment_sample_evaluations() - segment_samples_before_;
  p.stats = s;
  return p;
}

}  // namespace

AdaptiveBuildMemo::AdaptiveBuildMemo(const Surface& surface_, const Box& box_,
                                     const PartitionSettings& settings)
    : surface(surface_),
      box(box_),
      max_depth(settings.max_depth),
      edge_samples(settings.edge_samples),
      sampler(surface_),
      cache(sampler, make_lattice(box_, settings.max_depth), settings.edge_samples) {}

bool AdaptiveBuildMemo::fits(const Surface& s, const Box& b, const PartitionSettings& settings) const {
  return &s == &surface && b.lo == box.lo && b.hi == box.hi && settings.max_depth == max_depth &&
         settings.edge_samples == edge_samples;
}

Partition build_adaptive_partition(const Surface& surface, const Box& box, const PartitionSettings& settings,
                                   AdaptiveBuildMemo* memo) {
  if (memo && !memo->fits(surface, box, settings))
    throw Error(ErrorKind::Internal, "adaptive partition: a memo of another surface, box or lattice");
  std::optional<AdaptiveBuildMemo> own;
  AdaptiveBuildMemo& shared = memo ? *memo : own.emplace(surface, box, settings);
  return AdaptiveBuilder(surface, settings, shared).run();
}

}  // namespace isopatch
