// The crease loops of two smooth surfaces traced on a mesh of one of them (crease_loops.hpp).
#include "api/crease_loops.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <tbb/parallel_for.h>

#include "csg/crease_graph.hpp"
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

/// Puts every point on a = b = 0 from where it is (in parallel; each point its own).
void settle_all(std::vector<Vec3>& points, const Surface& a, const Surface& b, double edge,
                double tolerance) {
  CurvePointParams params;
  params.tolerance = tolerance;
  params.max_step = 0.5 * edge;
  params.max_travel = 2.0 * edge;
  params.max_iterations = 60;
  std::vector<std::uint8_t> failed(points.size(), 0);
  tbb::parallel_for(std::size_t{0}, points.size(), [&](std::size_t k) {
    const std::optional<Vec3> p = settle_on_curve(a, b, points[k], params);
    if (p)
      points[k] = *p;
    else
      failed[k] = 1;
  });
  for (std::size_t k = 0; k < points.size(); ++k)
    if (failed[k])
      throw CreaseError("the surfaces of max(a, b) meet tangentially near " + point_text(points[k]) +
                        ": their crease has no point there");
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

double loop_length(const std::vector<Vec3>& loop) {
  double length = 0.0;
  for (std::size_t k = 0; k < loop.size(); ++k) length += (loop[(k + 1) % loop.size()] - loop[k]).norm();
  return length;
}

}  // namespace

std::vector<CreaseLoop> trace_crease_loops(const Mesh& mesh_a, const Surface& a, const Surface& b,
                                           double edge, double tolerance) {
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
  // The crossings as points on the crease, in the order of the loops.
  std::vector<CreaseLoop> loops;
  std::vector<std::uint8_t> visited(crossing_edge.size(), 0);
  for (std::uint32_t start = 0; start < crossing_edge.size(); ++start) {
    if (visited[start]) continue;
    std::vector<std::uint32_t> chain;
    std::int64_t previous = -1, current = start;
    while (true) {
      const auto c = static_cast<std::uint32_t>(current);
      if (neighbour[c][1] < 0)
        throw CreaseError("the crease of max(a, b) leaves the box near " +
                          point_text(mesh_a.positions[crossing_edge[c][0]]) +
                          ": a curved cut is meshed when its solid lies inside the box");
      visited[c] = 1;
      chain.push_back(c);
      const std::int64_t next = neighbour[c][0] != previous ? neighbour[c][0] : neighbour[c][1];
      previous = current;
      current = next;
      if (current == static_cast<std::int64_t>(start)) break;
    }
    CreaseLoop loop;
    for (std::uint32_t c : chain) {
      const std::uint32_t u = crossing_edge[c][0], v = crossing_edge[c][1];
      const double t = value[u] / (value[u] - value[v]);
      loop.points.push_back(mesh_a.positions[u] + t * (mesh_a.positions[v] - mesh_a.positions[u]));
    }
    loops.push_back(std::move(loop));
  }
  // On both surfaces, evenly spaced, in the direction grad a x grad b.
  for (CreaseLoop& loop : loops) {
    settle_all(loop.points, a, b, edge, tolerance);
    for (int round = 0; round < kResampleRounds; ++round) {
      const double length = loop_length(loop.points);
      const auto count = std::max<std::size_t>(3, static_cast<std::size_t>(std::lround(length / edge)));
      loop.points = even_arc_length(loop.points, count);
      settle_all(loop.points, a, b, edge, tolerance);
    }
    double along = 0.0;
    const std::size_t m = loop.points.size();
    const double spacing = loop_length(loop.points) / static_cast<double>(m);
    for (std::size_t k = 0; k < m; ++k) {
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
