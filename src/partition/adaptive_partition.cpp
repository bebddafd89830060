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
#include "partition/leaf_tree.hpp"
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
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace isopatch {

namespace {

constexpr std::size_t kMaxLoopSize = 12;  // the patch templates' limit

struct Analysis {
  Leaf leaf;
  std::vector<SegmentKey> crossed;  // crossed segments of the boundary graph
  bool output = false;              // crossed, or an edge sample has the wrong sign
  bool split = false;               // wants splitting (ignoring max_depth and force_split)
  bool flat = false;                // a crossing lies inside one of the leaf's faces
};

// One (sub-)face polygon of a leaf's boundary graph.
struct Polygon {
  std::vector<LatticePoint> vertices;  // finest coordinates, counter-clockwise from outside
  FaceId face;
};

LatticePoint midpoint(const LatticePoint& a, const LatticePoint& b) {
  return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

LatticePoint twice(const LatticePoint& p) {
  return {2 * p[0], 2 * p[1], 2 * p[2]};
}

SegmentKey segment_between(const LatticePoint& a, const LatticePoint& b) {
  SegmentKey key;
  for (std::uint32_t axis = 0; axis < 3; ++axis) {
    if (a[axis] != b[axis]) {
      key.axis = axis;
      key.length = a[axis] < b[axis] ? b[axis] - a[axis] : a[axis] - b[axis];
    }
    key.start[axis] = std::min(a[axis], b[axis]);
  }
  return key;
}

class AdaptiveBuilder {
 public:
  AdaptiveBuilder(const Surface& surface, const PartitionSettings& settings, const Lattice& lattice)
      : surface_(surface),
        settings_(settings),
        lattice_(lattice),
        sampler_(surface),
        cache_(sampler_, lattice, settings.edge_samples),
        cos_cone_(std::cos(settings.cone_angle_deg * std::numbers::pi / 180.0)),
        tree_(settings.surface_depth, settings.max_depth) {}

  Partition run();

 private:
  Analysis analyse(const CellKey& key);
  std::vector<Polygon> boundary_polygons(const CellKey& key, const Cell& cell) const;
  bool segment_passes(const SegmentKey& key, const std::array<bool, 3>& monotone);
  std::array<bool, 3> monotone_axes(const Cell& cell);
  ComplexReason classify(const Cell& cell, const Analysis& a, bool ambiguous, bool edge_ok,
                         const std::array<bool, 6>& face_crossed);
  bool face_test(const Cell& cell, const std::array<bool, 6>& face_crossed);
  bool cone_test(const Cell& cell, const std::vector<Loop>& loops);
  bool oriented_along_gradient(const Loop& loop) const;
  bool close(const Analysis& a);
  std::uint32_t crossing(const SegmentKey& key);
  void check_cancel() const;
  Partition finish(std::vector<Analysis>& analyses);

  const Surface& surface_;
  const PartitionSettings& settings_;
  Lattice lattice_;
  Sampler sampler_;
  SampleCache cache_;
  double cos_cone_;
  LeafTree tree_;
  std::unordered_set<CellKey, CellKeyHash> forced_;  // force_split cells and their ancestors
  std::vector<Crossing> crossings_;
  IndexMap<SegmentKey, SegmentKeyHash> crossing_index_;  // same order as crossings_
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
  std::unordered_map<CellKey, Analysis, CellKeyHash> known;
  auto split = [&](const CellKey& key) {
    known.erase(key);
    for (const auto& o : face_edge_offsets()) {
      LatticePoint n = key.coords;
      for (int a = 0; a < 3; ++a) n[a] += static_cast<std::uint32_t>(o[a]);
      known.erase(CellKey{key.depth, n});
    }
  };
  std::vector<Analysis> analyses;
  for (;;) {
    check_cancel();
    ++stats_.adaptive_rounds;
    const std::vector<CellKey> balanced = tree_.balance();
    stats_.balance_splits += balanced.size();
    for (const CellKey& key : balanced) split(key);
    analyses.clear();
    std::vector<CellKey> to_split;
    bool changed = false;
    for (const CellKey& key : tree_.leaves()) {
      check_cancel();
      if (key.depth < settings_.max_depth && forced_.count(key)) {
        ++stats_.forced_splits;
        to_split.push_back(key);
        continue;
      }
      auto it = known.find(key);
      if (it == known.end()) {
        it = known.emplace(key, analyse(key)).first;
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
bool AdaptiveBuilder::close(const Analysis& a) {
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

std::vector<Polygon> AdaptiveBuilder::boundary_polygons(const CellKey& key, const Cell& cell) const {
  std::array<bool, 12> edge_split{};
  for (int e = 0; e < 12; ++e) {
    const int axis = cube::edge_axis(e);
    const auto& corner = cube::kCorner[cube::edge_lower_corner(e)];
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    std::array<int, 3> ou{}, ov{}, ouv{};
    ou[u] = ouv[u] = corner[u] ? 1 : -1;
    ov[v] = ouv[v] = corner[v] ? 1 : -1;
    edge_split[e] =
        tree_.neighbour_split(key, ou) || tree_.neighbour_split(key, ov) || tree_.neighbour_split(key, ouv);
  }
  std::vector<Polygon> polygons;
  for (int f = 0; f < 6; ++f) {
    std::array<int, 3> offset{};
    offset[cube::kFaceAxis[f]] = cube::kFaceSide[f] ? 1 : -1;
    std::array<LatticePoint, 4> p;
    for (int k = 0; k < 4; ++k) p[k] = cell.corner(cube::kFace[f][k]);
    if (!tree_.neighbour_split(key, offset)) {
      Polygon polygon{{}, cell.face(f)};
      for (int k = 0; k < 4; ++k) {
        polygon.vertices.push_back(p[k]);
        if (edge_split[cube::kFaceEdge[f][k]]) polygon.vertices.push_back(midpoint(p[k], p[(k + 1) % 4]));
      }
      polygons.push_back(std::move(polygon));
      continue;
    }
    // Quarters, each counter-clockwise like the face; each is a face of a finer neighbour.
    std::array<LatticePoint, 4> m;
    for (int k = 0; k < 4; ++k) m[k] = midpoint(p[k], p[(k + 1) % 4]);
    const LatticePoint c = midpoint(p[0], p[2]);
    const std::array<std::array<LatticePoint, 4>, 4> quarters = {
        {{p[0], m[0], c, m[3]}, {m[0], p[1], m[1], c}, {c, m[1], p[2], m[2]}, {m[3], c, m[2], p[3]}}};
    for (const auto& q : quarters) {
      FaceId id{q[0], static_cast<std::uint32_t>(cube::kFaceAxis[f]), cell.step / 2};
      for (const LatticePoint& x : q)
        for (int a = 0; a < 3; ++a) id.lower[a] = std::min(id.lower[a], x[a]);
      polygons.push_back(Polygon{{q.begin(), q.end()}, id});
    }
  }
  return polygons;
}

std::array<bool, 3> AdaptiveBuilder::monotone_axes(const Cell& cell) {
  std::array<bool, 3> monotone{};
  if (settings_.edge_samples == 0 || !settings_.use_intervals) return monotone;
  const auto bound = surface_.gradient_bound(lattice_.cell_box(cell.depth, cell.coords));
  if (bound) {
    ++stats_.interval_evaluations;
    for (int a = 0; a < 3; ++a)
      monotone[a] = !bound->gradient[a].empty() && !bound->gradient[a].contains_zero();
  }
  return monotone;
}

// Edge test (docs/algorithms.md 2.9.1) on one segment of the boundary graph.
bool AdaptiveBuilder::segment_passes(const SegmentKey& key, const std::array<bool, 3>& monotone) {
  if (settings_.edge_samples == 0) return true;
  if (monotone[key.axis]) {
    ++stats_.edges_certified_by_interval;
    return true;
  }
  const double first = cache_.value(twice(key.start));
  const double last = cache_.value(twice(key.end()));
  const int expected = is_negative(first) != is_negative(last) ? 1 : 0;
  return sign_changes(first, cache_.segment_samples(key), last) == expected;
}

Analysis AdaptiveBuilder::analyse(const CellKey& key) {
  const Cell cell = Cell::make(lattice_, key.depth, key.coords);
  Analysis a;
  a.leaf.depth = key.depth;
  a.leaf.coords = key.coords;
  a.leaf.box = lattice_.cell_box(key.depth, key.coords);
  if (!lattice_.inside(key.depth, key.coords)) return a;  // outside the box: empty
  for (int i = 0; i < 8; ++i)
    if (is_negative(cache_.value(cell.corner_half(i))))
      a.leaf.config = static_cast<std::uint8_t>(a.leaf.config | (1u << i));

  const std::vector<Polygon> polygons = boundary_polygons(key, cell);
  const std::array<bool, 3> monotone = monotone_axes(cell);
  bool edge_ok = true;
  bool ambiguous = false;
  bool broken = false;
  std::array<bool, 6> face_crossed{};
  struct Link {
    std::uint32_t to = 0;
    FaceId face;
    bool set = false;
  };
  std::vector<std::pair<std::uint32_t, Link>> links;  // from crossing -> link, in discovery order
  auto link_of = [&](std::uint32_t from) -> Link& {
    for (auto& [c, link] : links)
      if (c == from) return link;
    links.push_back({from, Link{}});
    return links.back().second;
  };
  std::unordered_set<SegmentKey, SegmentKeyHash> tested;
  for (std::size_t pi = 0; pi < polygons.size(); ++pi) {
    const Polygon& polygon = polygons[pi];
    const std::size_t m = polygon.vertices.size();
    std::array<bool, 8> negative{};  // a face polygon has at most 8 vertices (one midpoint per edge)
    for (std::size_t k = 0; k < m; ++k) negative[k] = is_negative(cache_.value(twice(polygon.vertices[k])));
    std::vector<SegmentKey> segments(m);
    int crossed = 0;
    for (std::size_t k = 0; k < m; ++k) {
      segments[k] = segment_between(polygon.vertices[k], polygon.vertices[next(k, m)]);
      if (tested.insert(segments[k]).second && !segment_passes(segments[k], monotone)) edge_ok = false;
      if (negative[k] != negative[next(k, m)]) ++crossed;
    }
    if (crossed == 0) continue;
    face_crossed[static_cast<std::size_t>(
        polygon.face.axis * 2 + (polygon.face.plane() == cell.lo[polygon.face.axis] ? 0 : 1))] = true;
    bool centre_negative = false;
    if (m == 4 && crossed == 4)
      centre_negative = is_negative(cache_.value({polygon.vertices[0][0] + polygon.vertices[2][0],
                                                  polygon.vertices[0][1] + polygon.vertices[2][1],
                                                  polygon.vertices[0][2] + polygon.vertices[2][2]}));
    const FaceLinks face_links = link_face(std::span<const bool>(negative.data(), m), centre_negative);
    ambiguous = ambiguous || face_links.ambiguous;
    broken = broken || face_links.unresolved;
    for (const FaceSide& side : face_links.sides) {
      const std::uint32_t from = crossing(segments[static_cast<std::size_t>(side.from)]);
      const std::uint32_t to = crossing(segments[static_cast<std::size_t>(side.to)]);
      Link& link = link_of(from);
      if (link.set) broken = true;
      link = Link{to, polygon.face, true};
      link_of(to);
    }
  }
  for (const auto& [c, link] : links) {
    a.crossed.push_back(crossings_[c].segment);
    const SegmentKey& s = crossings_[c].segment;
    int on_boundary = 0;
    for (std::uint32_t ax = 0; ax < 3; ++ax)
      if (ax != s.axis && (s.start[ax] == cell.lo[ax] || s.start[ax] == cell.lo[ax] + cell.step))
        ++on_boundary;
    if (on_boundary < 2) a.flat = true;
  }
  // Walk the cycles in discovery order.
  if (!broken) {
    std::unordered_set<std::uint32_t> visited;
    for (std::size_t i = 0; i < links.size() && !broken; ++i) {
      const std::uint32_t start = links[i].first;
      if (visited.count(start)) continue;
      Loop loop;
      std::uint32_t c = start;
      while (!visited.count(c)) {
        visited.insert(c);
        const auto it =
            std::find_if(links.begin(), links.end(), [c](const auto& entry) { return entry.first == c; });
        const Link& link = it->second;  // every crossing met was registered
        if (!link.set) {
          broken = true;
          break;
        }
        loop.corners.push_back(c);
        loop.side_faces.push_back(link.face);
        c = link.to;
      }
      if (broken || c != start) {
        broken = true;
        break;
      }
      a.leaf.loops.push_back(std::move(loop));
    }
  }
  if (broken) a.leaf.loops.clear();
  a.output = !links.empty() || !edge_ok;
  if (!a.output) return a;
  a.leaf.reason = broken ? ComplexReason::AmbiguousFace : classify(cell, a, ambiguous, edge_ok, face_crossed);
  a.leaf.kind = a.leaf.reason == ComplexReason::None ? LeafKind::Simple : LeafKind::Complex;
  bool bad_size = false;
  for (const Loop& loop : a.leaf.loops)
    bad_size = bad_size || loop.corners.size() < 3 || loop.corners.size() > kMaxLoopSize;
  switch (a.leaf.reason) {
    case ComplexReason::SeveralLoops:
    case ComplexReason::AmbiguousFace:
    case ComplexReason::EdgeTest:
    case ComplexReason::Orientation:
      a.split = true;
      break;
    default:
      a.split = bad_size || a.leaf.loops.size() != 1;
  }
  return a;
}

ComplexReason AdaptiveBuilder::classify(const Cell& cell, const Analysis& a, bool ambiguous, bool edge_ok,
                                        const std::array<bool, 6>& face_crossed) {
  if (ambiguous) return ComplexReason::AmbiguousFace;
  if (a.leaf.loops.size() > 1) return ComplexReason::SeveralLoops;
  if (!edge_ok) return ComplexReason::EdgeTest;
  if (settings_.face_test && !face_test(cell, face_crossed)) return ComplexReason::FaceTest;
  if (!cone_test(cell, a.leaf.loops)) return ComplexReason::NormalCone;
  for (const Loop& loop : a.leaf.loops)
    if (!oriented_along_gradient(loop)) return ComplexReason::Orientation;
  return ComplexReason::None;
}

// Face test (docs/algorithms.md 2.9.2) on every face whose boundary graph holds crossings;
// face_crossed is indexed by axis * 2 + side.
bool AdaptiveBuilder::face_test(const Cell& cell, const std::array<bool, 6>& face_crossed) {
  for (int f = 0; f < 6; ++f)
    if (face_crossed[static_cast<std::size_t>(cube::kFaceAxis[f] * 2 + cube::kFaceSide[f])] &&
        !face_gradients_agree(cache_, cell, f))
      return false;
  return true;
}

bool AdaptiveBuilder::cone_test(const Cell& cell, const std::vector<Loop>& loops) {
  return cell_gradients_within_cone(cache_, cell, loops, crossings_, cos_cone_);
}

bool AdaptiveBuilder::oriented_along_gradient(const Loop& loop) const {
  return loop_oriented_along_gradient(loop, crossings_);
}

// As Builder::crossing in build_partition.cpp: once per segment, from its negative end.
std::uint32_t AdaptiveBuilder::crossing(const SegmentKey& key) {
  if (const auto index = crossing_index_.find(key)) return *index;
  crossings_.push_back(segment_crossing(sampler_, lattice_, key, cache_.value(twice(key.start)),
                                        cache_.value(twice(key.end())), kSegmentRootTolerance,
                                        kSegmentRootIterations, stats_.root_evaluations));
  return crossing_index_.insert(key).first;
}

// Keeps the crossings the loops use, renumbered by segment key; leaves sorted by (depth, coords).
Partition AdaptiveBuilder::finish(std::vector<Analysis>& analyses) {
  std::vector<std::uint32_t> used;
  for (const Analysis& a : analyses)
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
  for (Analysis& a : analyses) {
    Leaf& leaf = a.leaf;
    for (Loop& loop : leaf.loops) {
      s.max_loop_size = std::max<std::uint64_t>(s.max_loop_size, loop.corners.size());
      if (!oriented_along_gradient(loop)) ++s.orientation_disagreements;
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
  s.value_evaluations = sampler_.value_count();
  s.gradient_evaluations = sampler_.gradient_count();
  s.segment_sample_evaluations = cache_.segment_sample_evaluations();
  p.stats = s;
  return p;
}

}  // namespace

Partition build_adaptive_partition(const Surface& surface, const Box& box,
                                   const PartitionSettings& settings) {
  return AdaptiveBuilder(surface, settings, make_lattice(box, settings.max_depth)).run();
}

}  // namespace isopatch
