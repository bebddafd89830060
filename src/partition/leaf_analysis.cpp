// The analysis of one leaf of the adaptive octree (leaf_analysis.hpp).
#include "partition/leaf_analysis.hpp"

#include <algorithm>
#include <span>
#include <unordered_set>

#include "core/cube_numbering.hpp"
#include "core/cyclic.hpp"
#include "partition/cell_checks.hpp"
#include "partition/cell_tests.hpp"
#include "partition/face_links.hpp"
#include "partition/octree_descent.hpp"
#include "surface/sign_rule.hpp"

namespace isopatch {
namespace {

constexpr std::size_t kMaxLoopSize = 12;  // the patch templates' limit

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

}  // namespace

std::vector<LeafAnalyser::Polygon> LeafAnalyser::boundary_polygons(const CellKey& key,
                                                                   const Cell& cell) const {
  std::array<bool, 12> edge_split{};
  for (int e = 0; e < 12; ++e) {
    const int axis = cube::edge_axis(e);
    const auto& corner = cube::kCorner[cube::edge_lower_corner(e)];
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    std::array<int, 3> ou{}, ov{}, ouv{};
    ou[u] = ouv[u] = corner[u] ? 1 : -1;
    ov[v] = ouv[v] = corner[v] ? 1 : -1;
    edge_split[e] = in_.tree.neighbour_split(key, ou) || in_.tree.neighbour_split(key, ov) ||
                    in_.tree.neighbour_split(key, ouv);
  }
  std::vector<Polygon> polygons;
  for (int f = 0; f < 6; ++f) {
    std::array<int, 3> offset{};
    offset[cube::kFaceAxis[f]] = cube::kFaceSide[f] ? 1 : -1;
    std::array<LatticePoint, 4> p;
    for (int k = 0; k < 4; ++k) p[k] = cell.corner(cube::kFace[f][k]);
    if (!in_.tree.neighbour_split(key, offset)) {
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

std::array<bool, 3> LeafAnalyser::monotone_axes(const Cell& cell) {
  std::array<bool, 3> monotone{};
  if (in_.settings.edge_samples == 0 || !in_.settings.use_intervals) return monotone;
  const auto bound = in_.surface.gradient_bound(in_.lattice.cell_box(cell.depth, cell.coords));
  if (bound) {
    ++stats_.interval_evaluations;
    for (int a = 0; a < 3; ++a)
      monotone[a] = !bound->gradient[a].empty() && !bound->gradient[a].contains_zero();
  }
  return monotone;
}

// Edge test (docs/algorithms.md 2.9.1) on one segment of the boundary graph.
bool LeafAnalyser::segment_passes(const SegmentKey& key, const std::array<bool, 3>& monotone) {
  if (in_.settings.edge_samples == 0) return true;
  if (monotone[key.axis]) {
    ++stats_.edges_certified_by_interval;
    return true;
  }
  const double first = cache_.value(twice(key.start));
  const double last = cache_.value(twice(key.end()));
  const int expected = is_negative(first) != is_negative(last) ? 1 : 0;
  return sign_changes(first, cache_.segment_samples(key), last) == expected;
}

LeafAnalysis LeafAnalyser::analyse(const CellKey& key) {
  const Cell cell = Cell::make(in_.lattice, key.depth, key.coords);
  LeafAnalysis a;
  a.leaf.depth = key.depth;
  a.leaf.coords = key.coords;
  a.leaf.box = in_.lattice.cell_box(key.depth, key.coords);
  if (!in_.lattice.inside(key.depth, key.coords)) return a;  // outside the box: empty
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

ComplexReason LeafAnalyser::classify(const Cell& cell, const LeafAnalysis& a, bool ambiguous, bool edge_ok,
                                     const std::array<bool, 6>& face_crossed) {
  if (ambiguous) return ComplexReason::AmbiguousFace;
  if (a.leaf.loops.size() > 1) return ComplexReason::SeveralLoops;
  if (!edge_ok) return ComplexReason::EdgeTest;
  if (in_.settings.face_test && !face_test(cell, face_crossed)) return ComplexReason::FaceTest;
  if (!cone_test(cell, a.leaf.loops)) return ComplexReason::NormalCone;
  for (const Loop& loop : a.leaf.loops)
    if (!oriented_along_gradient(loop)) return ComplexReason::Orientation;
  return ComplexReason::None;
}

// Face test (docs/algorithms.md 2.9.2) on every face whose boundary graph holds crossings;
// face_crossed is indexed by axis * 2 + side.
bool LeafAnalyser::face_test(const Cell& cell, const std::array<bool, 6>& face_crossed) {
  for (int f = 0; f < 6; ++f)
    if (face_crossed[static_cast<std::size_t>(cube::kFaceAxis[f] * 2 + cube::kFaceSide[f])] &&
        !face_gradients_agree(cache_, cell, f))
      return false;
  return true;
}

bool LeafAnalyser::cone_test(const Cell& cell, const std::vector<Loop>& loops) {
  return cell_gradients_within_cone(cache_, cell, loops, crossings_, in_.cos_cone);
}

bool LeafAnalyser::oriented_along_gradient(const Loop& loop) const {
  return loop_oriented_along_gradient(loop, crossings_);
}

// As Builder::crossing in build_partition.cpp: once per segment, from its negative end; a crossing
// the shared list already holds is copied (the same numbers: a function of the segment alone).
std::uint32_t LeafAnalyser::crossing(const SegmentKey& key) {
  if (const auto index = crossing_index_.find(key)) return *index;
  if (const auto shared = in_.crossing_index.find(key))
    crossings_.push_back(in_.crossings[*shared]);
  else
    crossings_.push_back(segment_crossing(in_.sampler, in_.lattice, key, cache_.value(twice(key.start)),
                                          cache_.value(twice(key.end())), kSegmentRootTolerance,
                                          kSegmentRootIterations, stats_.root_evaluations));
  return crossing_index_.insert(key).first;
}

}  // namespace isopatch
