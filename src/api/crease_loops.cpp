// The crease loops of two smooth surfaces traced on a mesh of one of them (crease_loops.hpp).
#include "api/crease_loops.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <tbb/parallel_for.h>

#include "csg/crease_graph.hpp"
#include "csg/face_set.hpp"
#include "surface/curve_point.hpp"

namespace isopatch {

namespace {

/// Rounds of resampling at even arc length (each settles the points again).
constexpr int kResampleRounds = 3;
/// A resampled loop whose neighbouring points come closer than this share of an edge has folded.
constexpr double kFoldedSpacing = 0.15;

std::uint64_t undirected_key(std::uint32_t u, std::uint32_t v) {
  if (u > v) std::swap(u, v);
  return (static_cast<std::uint64_t>(u) << 32) | v;
}

CurvePointParams settle_params(double edge, double tolerance) {
  CurvePointParams params;
  params.tolerance = tolerance;
  params.max_step = 0.5 * edge;
  params.max_travel = 2.0 * edge;
  params.max_iterations = 60;
  return params;
}

/// Puts the points [first, last) on a = b = 0 from where they are (in parallel; each point its own).
void settle_all(std::vector<Vec3>& points, const Surface& a, const Surface& b, double edge, double tolerance,
                std::size_t first, std::size_t last) {
  const CurvePointParams params = settle_params(edge, tolerance);
  std::vector<std::uint8_t> failed(points.size(), 0);
  tbb::parallel_for(first, last, [&](std::size_t k) {
    const std::optional<Vec3> p = settle_on_curve(a, b, points[k], params);
    if (p)
      points[k] = *p;
    else
      failed[k] = 1;
  });
  for (std::size_t k = first; k < last; ++k)
    if (failed[k])
      throw ShapeNotManifoldError("the surfaces of max(a, b) meet tangentially near " +
                                  point_text(points[k]) + ": their crease has no point there");
}

/// The end of an arc where the crease leaves the box: the point of a = b = 0 on the face of `box` that
/// the boundary edge (u, v) of the mesh lies on, near `p`, with that coordinate exactly the face's.
Vec3 arc_end(const Vec3& p, const Vec3& u, const Vec3& v, const Surface& a, const Surface& b, const Box& box,
             double edge, double tolerance) {
  const double on = 1e-9 * box.diagonal();
  int axis = -1;
  double level = 0.0;
  int faces = 0;
  for (int k = 0; k < 3; ++k)
    for (const double c : {box.lo[k], box.hi[k]})
      if (std::abs(u[k] - c) <= on && std::abs(v[k] - c) <= on) {
        axis = k;
        level = c;
        ++faces;
      }
  if (faces != 1)
    throw CreaseError("the crease of max(a, b) leaves the box " +
                      std::string(faces == 0 ? "off its faces" : "at an edge of it") + " near " +
                      point_text(p));
  const SurfacePtr face = plane_surface(Vec3::Unit(axis), level, box);
  const std::optional<Vec3> end = settle_on_corner(a, b, *face, p, settle_params(edge, tolerance));
  if (!end)
    throw CreaseError("the surfaces of max(a, b) meet tangentially, or along the box, near " + point_text(p) +
                      ": their crease has no point where it leaves the box");
  Vec3 out = *end;
  out[axis] = level;
  return out;
}

/// The closed polyline `loop` resampled at `count` points of even arc length, starting at its first.
std::vector<Vec3> even_arc_length(const std::vector<Vec3>& loop, std::size_t count) {
  std::vector<double> s(loop.size() + 1, 0.0);
  for (std::size_t k = 0; k < loop.size(); ++k)
    s[k + 1] = s[k] + (loop[(k + 1) % loop.size()] - loop[k]).norm();
  const double length = s.back();
  std::vector<Vec3> out;
  out.reserve(count);
  std::size_t segment = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double target = length * static_cast<double>(k) / static_cast<double>(count);
    while (segment + 1 < loop.size() && s[segment + 1] <= target) ++segment;
    const double piece = s[segment + 1] - s[segment];
    const double t = piece > 0.0 ? (target - s[segment]) / piece : 0.0;
    out.push_back(loop[segment] + t * (loop[(segment + 1) % loop.size()] - loop[segment]));
  }
  return out;
}

/// The open polyline `arc` resampled at `segments` + 1 points of even arc length, its ends kept.
std::vector<Vec3> even_arc_length_open(const std::vector<Vec3>& arc, std::size_t segments) {
  std::vector<double> s(arc.size(), 0.0);
  for (std::size_t k = 1; k < arc.size(); ++k) s[k] = s[k - 1] + (arc[k] - arc[k - 1]).norm();
  std::vector<Vec3> out{arc.front()};
  std::size_t segment = 0;
  for (std::size_t k = 1; k < segments; ++k) {
    const double target = s.back() * static_cast<double>(k) / static_cast<double>(segments);
    while (segment + 2 < arc.size() && s[segment + 1] <= target) ++segment;
    const double piece = s[segment + 1] - s[segment];
    const double t = piece > 0.0 ? (target - s[segment]) / piece : 0.0;
    out.push_back(arc[segment] + t * (arc[segment + 1] - arc[segment]));
  }
  out.push_back(arc.back());
  return out;
}

/// The length of a polyline, closed or open.
double curve_length(const std::vector<Vec3>& points, bool closed) {
  double length = 0.0;
  const std::size_t segments = closed ? points.size() : points.size() - 1;
  for (std::size_t k = 0; k < segments; ++k) length += (points[(k + 1) % points.size()] - points[k]).norm();
  return length;
}

}  // namespace

std::vector<CreaseLoop> trace_crease_loops(const Mesh& mesh_a, const Surface& a, const Surface& b,
                                           double edge, double tolerance, const Box* open_at) {
  const std::size_t n = mesh_a.positions.size();
  std::vector<double> value(n);
  b.values(mesh_a.positions, value);
  for (std::size_t v = 0; v < n; ++v)
    if (!std::isfinite(value[v]))
      throw EvaluationError("the cutting surface is not finite at " + point_text(mesh_a.positions[v]));
  const auto inside = [&value](std::uint32_t v) { return value[v] < 0.0; };
  // Crossings: one per edge whose ends lie on both sides of b = 0, and the triangles beside each.
  std::unordered_map<std::uint64_t, std::uint32_t> crossing_of;
  std::vector<std::array<std::uint32_t, 2>> crossing_edge;
  std::vector<std::array<std::int64_t, 2>> neighbour;  // the crossing across each triangle beside it
  const auto crossing = [&](std::uint32_t u, std::uint32_t v) {
    const auto [it, added] =
        crossing_of.emplace(undirected_key(u, v), static_cast<std::uint32_t>(crossing_edge.size()));
    if (added) {
      crossing_edge.push_back({u, v});
      neighbour.push_back({-1, -1});
    }
    return it->second;
  };
  const auto link = [&](std::uint32_t from, std::uint32_t to) {
    std::array<std::int64_t, 2>& slot = neighbour[from];
    if (slot[0] < 0)
      slot[0] = to;
    else if (slot[1] < 0)
      slot[1] = to;
    else
      throw CreaseError("the mesh of the lattice is not a 2-manifold where its crease runs, near " +
                        point_text(mesh_a.positions[crossing_edge[from][0]]));
  };
  for (const Triangle& t : mesh_a.triangles) {
    std::array<std::uint32_t, 2> cut{};
    int cuts = 0;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = t[static_cast<std::size_t>(k)], v = t[static_cast<std::size_t>((k + 1) % 3)];
      if (inside(u) != inside(v)) cut[static_cast<std::size_t>(cuts++)] = crossing(u, v);
    }
    if (cuts == 2) {
      link(cut[0], cut[1]);
      link(cut[1], cut[0]);
    }
  }
  const auto crossing_point = [&](std::uint32_t c) {
    const std::uint32_t u = crossing_edge[c][0], v = crossing_edge[c][1];
    const double t = value[u] / (value[u] - value[v]);
    return Vec3(mesh_a.positions[u] + t * (mesh_a.positions[v] - mesh_a.positions[u]));
  };
  // A crossing with one triangle beside it lies on the mesh's boundary: the crease leaves the box there.
  const auto is_end = [&](std::uint32_t c) { return neighbour[c][1] < 0; };
  std::vector<std::uint8_t> visited(crossing_edge.size(), 0);
  // The chain of crossings from `start` (an end: to the other end; else around to `start`).
  const auto chain_from = [&](std::uint32_t start) {
    std::vector<std::uint32_t> chain;
    std::int64_t previous = -1, current = start;
    while (true) {
      const auto c = static_cast<std::uint32_t>(current);
      visited[c] = 1;
      chain.push_back(c);
      const std::int64_t next = neighbour[c][0] != previous ? neighbour[c][0] : neighbour[c][1];
      if (next < 0 || (chain.size() > 1 && is_end(c))) break;
      previous = current;
      current = next;
      if (current == static_cast<std::int64_t>(start)) break;
    }
    return chain;
  };
  std::vector<CreaseLoop> arcs, loops;
  for (std::uint32_t start = 0; start < crossing_edge.size(); ++start) {
    if (visited[start] || !is_end(start)) continue;
    if (open_at == nullptr)
      throw CreaseError("the crease of max(a, b) leaves the box near " +
                        point_text(mesh_a.positions[crossing_edge[start][0]]) +
                        ": a curved cut is meshed when its solid lies inside the box");
    const std::vector<std::uint32_t> chain = chain_from(start);
    CreaseLoop arc;
    arc.closed = false;
    for (std::uint32_t c : chain) arc.points.push_back(crossing_point(c));
    for (const std::uint32_t c : {chain.front(), chain.back()}) {
      Vec3& end = c == chain.front() ? arc.points.front() : arc.points.back();
      end = arc_end(end, mesh_a.positions[crossing_edge[c][0]], mesh_a.positions[crossing_edge[c][1]], a, b,
                    *open_at, edge, tolerance);
    }
    if (chain.size() < 2 || !is_end(chain.back()))
      throw CreaseError("the crease of max(a, b) ends inside the box near " + point_text(arc.points.back()));
    arcs.push_back(std::move(arc));
  }
  for (std::uint32_t start = 0; start < crossing_edge.size(); ++start) {
    if (visited[start]) continue;
    CreaseLoop loop;
    for (std::uint32_t c : chain_from(start)) loop.points.push_back(crossing_point(c));
    loops.push_back(std::move(loop));
  }
  for (CreaseLoop& arc : arcs) loops.push_back(std::move(arc));
  // On both surfaces, evenly spaced, in the direction grad a x grad b (an arc's ends stay where they are).
  for (CreaseLoop& loop : loops) {
    const std::size_t inner = loop.closed ? 0 : 1;
    settle_all(loop.points, a, b, edge, tolerance, inner, loop.points.size() - inner);
    for (int round = 0; round < kResampleRounds; ++round) {
      const double length = curve_length(loop.points, loop.closed);
      const auto count = static_cast<std::size_t>(std::lround(length / edge));
      loop.points = loop.closed ? even_arc_length(loop.points, std::max<std::size_t>(3, count))
                                : even_arc_length_open(loop.points, std::max<std::size_t>(2, count));
      settle_all(loop.points, a, b, edge, tolerance, inner, loop.points.size() - inner);
    }
    double along = 0.0;
    const std::size_t m = loop.points.size(), segments = loop.closed ? m : m - 1;
    const double spacing = curve_length(loop.points, loop.closed) / static_cast<double>(segments);
    for (std::size_t k = 0; k < segments; ++k) {
      const Vec3& p = loop.points[k];
      const Vec3 step = loop.points[(k + 1) % m] - p;
      if (step.norm() < kFoldedSpacing * spacing)
        throw CreaseError("the crease of max(a, b) folds near " + point_text(p) +
                          ": two crease curves closer than an edge; a smaller edge length");
      along += step.dot(a.value_gradient(p).gradient.cross(b.value_gradient(p).gradient));
    }
    if (along < 0.0) std::reverse(loop.points.begin(), loop.points.end());
  }
  return loops;
}

}  // namespace isopatch
