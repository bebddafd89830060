// flat_disc (flat_discs.hpp).
#include "analysis/flat_discs.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>

#include "analysis/segments_2d.hpp"

namespace isopatch::analysis {
namespace {

struct BoundaryEdge {
  std::uint32_t from = 0, to = 0;
};

/// The boundary edges of the triangles at positions [begin, end) (b of flat_discs.hpp: false at a
/// tangled edge), in the direction of their triangle.
bool boundary_edges(const OrderedTriangles& s, std::uint32_t begin, std::uint32_t end,
                    std::vector<BoundaryEdge>& out) {
  for (std::uint32_t p = begin; p < end; ++p) {
    const std::uint32_t t = (*s.order)[p];
    const Triangle& tri = s.mesh->triangles[t];
    for (std::size_t e = 0; e < 3; ++e) {
      const std::uint32_t u = s.fans->neighbours[3 * std::size_t{t} + e];
      if (u == MeshFans::kTangled) return false;
      if (u == MeshFans::kOpen || s.position[u] < begin || s.position[u] >= end)
        out.push_back({tri[e], tri[(e + 1) % 3]});
    }
  }
  return true;
}

/// Whether boundary edges that meet at vertex p (their other ends a and c) overlap beyond p: a and c on
/// one ray from p.
bool fold_back(Point2 p, Point2 a, Point2 c) {
  if (orient2d(p, a, c) != 0) return false;
  const auto sign = [](double d) { return (d > 0.0 ? 1 : 0) - (d < 0.0 ? 1 : 0); };
  return sign(a.x - p.x) == sign(c.x - p.x) && sign(a.y - p.y) == sign(c.y - p.y);
}

/// The boundary edges projected, with the extents of their segments.
struct Segment {
  Point2 a, b;
  double lo_x = 0, hi_x = 0, lo_y = 0, hi_y = 0;
  std::uint32_t from = 0, to = 0;
};

/// The edges under the projection dropping `axis`, mirrored (x and y swapped) when `mirrored`, so that
/// triangles turning clockwise under the projection turn counter-clockwise under the mirrored one.
std::vector<Segment> projected(const Mesh& mesh, const std::vector<BoundaryEdge>& edges, int axis,
                               bool mirrored) {
  const auto project = [&](std::uint32_t v) {
    const Point2 p = drop_axis(mesh.positions[v], axis);
    return mirrored ? Point2{p.y, p.x} : p;
  };
  std::vector<Segment> segments(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    Segment& s = segments[k];
    s.a = project(edges[k].from);
    s.b = project(edges[k].to);
    s.lo_x = std::min(s.a.x, s.b.x), s.hi_x = std::max(s.a.x, s.b.x);
    s.lo_y = std::min(s.a.y, s.b.y), s.hi_y = std::max(s.a.y, s.b.y);
    s.from = edges[k].from, s.to = edges[k].to;
  }
  return segments;
}

/// Whether segments s and t meet other than at a vertex they share by index (c of flat_discs.hpp).
bool segments_cross(const Segment& s, const Segment& t) {
  if ((s.from == t.to && s.to == t.from) || (s.from == t.from && s.to == t.to)) return true;
  if (s.to == t.from) return fold_back(s.b, s.a, t.b);
  if (t.to == s.from) return fold_back(s.a, s.b, t.a);
  if (s.from == t.from) return fold_back(s.a, s.b, t.b);
  if (s.to == t.to) return fold_back(s.b, s.a, t.a);
  return segments_meet_2d(s.a, s.b, t.a, t.b);
}

/// (c) of flat_discs.hpp: no two segments meet other than at a vertex they share. A sweep along x over
/// their extents; pairs whose boxes overlap are tested exactly.
bool apart_in_projection(const std::vector<Segment>& segments) {
  std::vector<std::uint32_t> by_x(segments.size());
  std::iota(by_x.begin(), by_x.end(), 0U);
  std::sort(by_x.begin(), by_x.end(), [&](std::uint32_t i, std::uint32_t j) {
    return segments[i].lo_x < segments[j].lo_x || (segments[i].lo_x == segments[j].lo_x && i < j);
  });
  for (std::size_t m = 0; m < by_x.size(); ++m) {
    const Segment& s = segments[by_x[m]];
    for (std::size_t n = m + 1; n < by_x.size() && segments[by_x[n]].lo_x <= s.hi_x; ++n) {
      const Segment& t = segments[by_x[n]];
      if (t.lo_y <= s.hi_y && s.lo_y <= t.hi_y && segments_cross(s, t)) return false;
    }
  }
  return true;
}

/// Directions from a point p to the other ends of its edges, in counter-clockwise order from the
/// direction +x: the upper half-plane (y above p, or level and x right of it) first, then by turn.
bool turns_before(Point2 p, Point2 a, Point2 b) {
  const auto upper = [&](Point2 q) { return q.y > p.y || (q.y == p.y && q.x > p.x); };
  if (upper(a) != upper(b)) return upper(a);
  return orient2d(p, a, b) > 0;
}

/// The boundary graph under one projection: its segments sorted by `from`, and by `to`.
struct Graph {
  std::vector<Segment> by_from, by_to;
  /// The index in by_from of the first segment from v, or by_from.size().
  std::size_t first_from(std::uint32_t v) const {
    const auto it = std::lower_bound(by_from.begin(), by_from.end(), v,
                                     [](const Segment& s, std::uint32_t w) { return s.from < w; });
    return it != by_from.end() && it->from == v ? static_cast<std::size_t>(it - by_from.begin())
                                                : by_from.size();
  }
};

struct Spoke {
  Point2 end;
  bool out = false;
};

/// The boundary edges at the vertex where by_from[k] starts, in counter-clockwise order (turns_before);
/// empty when it has not as many in as out.
std::vector<Spoke> spokes_at(const Graph& g, std::size_t k) {
  const std::uint32_t v = g.by_from[k].from;
  const Point2 p = g.by_from[k].a;
  std::vector<Spoke> spokes;
  std::size_t outs = 0;
  for (std::size_t m = k; m < g.by_from.size() && g.by_from[m].from == v; ++m, ++outs)
    spokes.push_back({g.by_from[m].b, true});
  const auto in = std::lower_bound(g.by_to.begin(), g.by_to.end(), v,
                                   [](const Segment& s, std::uint32_t w) { return s.to < w; });
  for (auto it = in; it != g.by_to.end() && it->to == v; ++it) spokes.push_back({it->a, false});
  if (spokes.size() != 2 * outs) return {};
  std::sort(spokes.begin(), spokes.end(),
            [&](const Spoke& a, const Spoke& b) { return turns_before(p, a.end, b.end); });
  return spokes;
}

/// (d) of flat_discs.hpp: around every vertex with more than one outgoing boundary edge, the edges
/// alternate out and in.
bool alternate_at_pinches(const Graph& g) {
  for (std::size_t k = 0; k < g.by_from.size();) {
    std::size_t last = k + 1;
    while (last < g.by_from.size() && g.by_from[last].from == g.by_from[k].from) ++last;
    if (last - k > 1) {
      const std::vector<Spoke> spokes = spokes_at(g, k);
      if (spokes.empty()) return false;
      for (std::size_t m = 0; m < spokes.size(); ++m)
        if (spokes[m].out == spokes[(m + 1) % spokes.size()].out) return false;
    }
    k = last;
  }
  return true;
}

/// Boundaries made of more pieces are not tried (the nesting test compares every pair).
constexpr std::size_t kMostPieces = 16;

/// (e) of flat_discs.hpp: the connected pieces of the boundary graph, each with its side (+1 when its
/// faces left of its edges are the inner ones, -1 when they are the outer ones), nest so that the
/// winding number stays 0 or 1: for each piece j, the other pieces wind around its vertices 0 times
/// (side +1) or once (side -1).
bool nested_consistently(const Graph& g) {
  const std::size_t n = g.by_from.size();
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0U);
  const auto root = [&](std::uint32_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  const auto join = [&](std::size_t a, std::size_t b) {
    const std::uint32_t ra = root(static_cast<std::uint32_t>(a)), rb = root(static_cast<std::uint32_t>(b));
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
  };
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = g.first_from(g.by_from[k].to);
    if (next == n) return false;  // an edge into a vertex with none out
    join(k, next);
    if (k > 0 && g.by_from[k].from == g.by_from[k - 1].from) join(k, k - 1);
  }
  // Per piece: its lowest vertex (least y, then x), whose edges all point into the upper half-plane, so
  // the outer face lies clockwise of the first of them in counter-clockwise order.
  std::array<std::uint32_t, kMostPieces> pieces{};
  std::size_t count = 0;
  std::vector<std::size_t> lowest(n, n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t r = root(static_cast<std::uint32_t>(k));
    if (lowest[r] == n) {
      if (count == kMostPieces) return false;
      pieces[count++] = r;
      lowest[r] = k;
    }
    const Point2 a = g.by_from[k].a, b = g.by_from[lowest[r]].a;
    if (a.y < b.y || (a.y == b.y && a.x < b.x)) lowest[r] = k;
  }
  std::array<int, kMostPieces> side{};
  for (std::size_t i = 0; i < count; ++i) {
    std::size_t first = lowest[pieces[i]];
    while (first > 0 && g.by_from[first - 1].from == g.by_from[first].from) --first;
    const std::vector<Spoke> spokes = spokes_at(g, first);
    if (spokes.empty()) return false;
    side[i] = spokes.front().out ? 1 : -1;  // outer face right of an edge out, left of an edge in
  }
  if (count == 1) return side[0] == 1;
  // The winding number around p of the pieces other than `piece`: crossings of the ray from p towards
  // +x (p lies on none of their edges, by c).
  const auto winding_of_others = [&](std::uint32_t piece, Point2 p) {
    int w = 0;
    for (std::size_t k = 0; k < n; ++k) {
      if (root(static_cast<std::uint32_t>(k)) == piece) continue;
      const Segment& s = g.by_from[k];
      if (s.a.y <= p.y && s.b.y > p.y && orient2d(s.a, s.b, p) > 0) ++w;
      if (s.b.y <= p.y && s.a.y > p.y && orient2d(s.a, s.b, p) < 0) --w;
    }
    return w;
  };
  for (std::size_t j = 0; j < count; ++j)
    if (winding_of_others(pieces[j], g.by_from[lowest[pieces[j]]].a) != (side[j] == 1 ? 0 : 1)) return false;
  return true;
}

}  // namespace

bool flat_disc(const OrderedTriangles& triangles, std::uint32_t begin, std::uint32_t end, std::uint8_t turns,
               std::vector<std::uint32_t>* boundary) {
  if ((turns & 0x3FU) == 0) return false;
  std::vector<BoundaryEdge> edges;
  if (!boundary_edges(triangles, begin, end, edges) || edges.size() < 3) return false;
  std::sort(edges.begin(), edges.end(), [](const BoundaryEdge& a, const BoundaryEdge& b) {
    return a.from < b.from || (a.from == b.from && a.to < b.to);
  });
  for (int axis = 0; axis < 3; ++axis) {
    if ((turns & (9U << static_cast<unsigned>(axis))) == 0) continue;
    Graph g;
    // Triangles that turn clockwise (bit 3 + axis) are seen in a mirror: counter-clockwise, as (e) reads.
    g.by_from = projected(*triangles.mesh, edges, axis, (turns & (1U << static_cast<unsigned>(axis))) == 0);
    if (!apart_in_projection(g.by_from)) continue;
    g.by_to = g.by_from;
    std::sort(g.by_to.begin(), g.by_to.end(), [](const Segment& a, const Segment& b) { return a.to < b.to; });
    if (alternate_at_pinches(g) && nested_consistently(g)) {
      if (boundary != nullptr)
        for (std::size_t k = 0; k < edges.size(); ++k)
          if (k == 0 || edges[k].from != edges[k - 1].from) boundary->push_back(edges[k].from);
      return true;
    }
  }
  return false;
}

}  // namespace isopatch::analysis
