// The boundary loops of a face cut open by the box (box_boundary_loops.hpp).
#include "api/box_boundary_loops.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "api/band_join.hpp"
#include "csg/crease_graph.hpp"

namespace isopatch {

namespace {

std::uint64_t directed_edge_key(std::uint32_t u, std::uint32_t v) {
  return (static_cast<std::uint64_t>(u) << 32) | v;
}

/// The distance from p to the segment [u, v].
double to_segment(const Vec3& p, const Vec3& u, const Vec3& v) {
  const Vec3 d = v - u;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - u).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (p - (u + t * d)).norm();
}

/// A boundary edge where o changes sign: the loop, and the index of its first vertex there.
struct Crossing {
  std::size_t loop = 0, index = 0;
};

}  // namespace

std::vector<std::vector<std::uint32_t>> triangle_boundary_loops(const std::vector<Triangle>& triangles) {
  std::unordered_set<std::uint64_t> half;
  half.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
    for (std::size_t k = 0; k < 3; ++k) half.insert(directed_edge_key(t[k], t[(k + 1) % 3]));
  std::map<std::uint32_t, std::uint32_t> next;
  for (const Triangle& t : triangles)
    for (std::size_t k = 0; k < 3; ++k)
      if (!half.count(directed_edge_key(t[(k + 1) % 3], t[k]))) next[t[k]] = t[(k + 1) % 3];
  std::vector<std::vector<std::uint32_t>> loops;
  std::unordered_set<std::uint32_t> used;
  for (const auto& [first, unused] : next) {
    if (used.count(first)) continue;
    std::vector<std::uint32_t> loop;
    for (std::uint32_t v = first; !used.count(v);) {
      used.insert(v);
      loop.push_back(v);
      const auto it = next.find(v);
      if (it == next.end()) break;
      v = it->second;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<std::vector<BoundaryPoint>> box_boundary_loops(const Mesh& mesh,
                                                           const std::vector<std::uint8_t>& inside,
                                                           const std::vector<std::vector<Vec3>>& arcs,
                                                           double reach) {
  const std::vector<std::vector<std::uint32_t>> loops = triangle_boundary_loops(mesh.triangles);
  std::vector<std::vector<BoundaryPoint>> out;
  // Where o turns positive along a loop (an arc leaves there) and where it turns negative (one arrives).
  std::vector<Crossing> leaving, arriving;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::vector<std::uint32_t>& loop = loops[l];
    bool crossed = false;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const bool here = inside[loop[i]] != 0, there = inside[loop[(i + 1) % loop.size()]] != 0;
      if (here && !there) leaving.push_back({l, i});
      if (!here && there) arriving.push_back({l, i});
      crossed = crossed || here != there;
    }
    if (!crossed && inside[loop.front()]) {
      std::vector<BoundaryPoint> whole;
      whole.reserve(loop.size());
      for (std::uint32_t v : loop) whole.push_back({-1, v});
      out.push_back(std::move(whole));
    }
  }
  // Each arc's ends matched to the crossings nearest to them.
  const auto match = [&](const std::vector<Crossing>& crossings, bool first) {
    std::vector<std::optional<std::size_t>> of_arc(arcs.size());
    std::vector<std::uint8_t> taken(crossings.size(), 0);
    for (std::size_t c = 0; c < arcs.size(); ++c) {
      const Vec3& end = first ? arcs[c].front() : arcs[c].back();
      double best = reach;
      for (std::size_t k = 0; k < crossings.size(); ++k) {
        const std::vector<std::uint32_t>& loop = loops[crossings[k].loop];
        const std::size_t i = crossings[k].index;
        const double d =
            to_segment(end, mesh.positions[loop[i]], mesh.positions[loop[(i + 1) % loop.size()]]);
        if (!taken[k] && d <= best) {
          best = d;
          of_arc[c] = k;
        }
      }
      if (!of_arc[c])
        throw CreaseError(
            "the crease of max(a, b) reaches the box near " + point_text(end) +
            " where the face's boundary on the box does not cross it: creases closer than an edge "
            "at the box");
      taken[*of_arc[c]] = 1;
    }
    for (std::size_t k = 0; k < crossings.size(); ++k)
      if (!taken[k]) {
        const Crossing& x = crossings[k];
        throw CreaseError("the face's boundary on the box crosses the other solid near " +
                          point_text(mesh.positions[loops[x.loop][x.index]]) +
                          " with no crease there: creases closer than an edge at the box");
      }
    return of_arc;
  };
  const std::vector<std::optional<std::size_t>> starts = match(leaving, true), ends = match(arriving, false);
  // The arc that leaves at each crossing where o turns positive.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> leaving_arc;
  for (std::size_t c = 0; c < arcs.size(); ++c) {
    const Crossing& x = leaving[*starts[c]];
    leaving_arc[{x.loop, x.index}] = c;
  }
  std::vector<std::uint8_t> done(arcs.size(), 0);
  for (std::size_t first = 0; first < arcs.size(); ++first) {
    if (done[first]) continue;
    std::vector<BoundaryPoint> loop;
    for (std::size_t c = first; !done[c];) {
      done[c] = 1;
      for (std::size_t k = 0; k < arcs[c].size(); ++k)
        loop.push_back({static_cast<std::int64_t>(c), static_cast<std::uint32_t>(k)});
      // Along the mesh's boundary from where the arc arrives to where o turns positive again.
      const Crossing& x = arriving[*ends[c]];
      const std::vector<std::uint32_t>& around = loops[x.loop];
      std::size_t i = (x.index + 1) % around.size();
      for (std::size_t steps = 0; inside[around[i]] && steps < around.size(); ++steps) {
        loop.push_back({-1, around[i]});
        if (!inside[around[(i + 1) % around.size()]]) break;
        i = (i + 1) % around.size();
      }
      const auto next = leaving_arc.find({x.loop, i});
      if (next == leaving_arc.end())
        throw CreaseError("the face's boundary on the box does not lead from one crease to the next near " +
                          point_text(mesh.positions[around[i]]) + ": creases closer than an edge at the box");
      c = next->second;
    }
    out.push_back(std::move(loop));
  }
  return out;
}

std::optional<BoxJoin> join_at_the_box(const std::vector<Vec3>& positions,
                                       const std::vector<std::vector<std::uint32_t>>& loops,
                                       const std::vector<std::vector<std::uint32_t>>& boundary,
                                       std::string& failure) {
  // Where each vertex of F's loops lies on them.
  std::unordered_map<std::uint32_t, std::pair<std::size_t, std::size_t>> on_loop;
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (std::size_t k = 0; k < loops[l].size(); ++k) on_loop[loops[l][k]] = {l, k};
  BoxJoin out;
  std::vector<std::vector<std::uint8_t>> covered(loops.size());
  std::vector<std::uint8_t> touched(loops.size(), 0);
  for (std::size_t l = 0; l < loops.size(); ++l) covered[l].assign(loops[l].size(), 0);
  for (const std::vector<std::uint32_t>& b : boundary) {
    std::vector<std::size_t> shared;
    for (std::size_t i = 0; i < b.size(); ++i)
      if (on_loop.count(b[i])) shared.push_back(i);
    if (shared.empty()) {
      out.free_boundary.push_back(b);
      continue;
    }
    for (std::size_t s = 0; s < shared.size(); ++s) {
      const std::size_t i = shared[s], j = shared[(s + 1) % shared.size()];
      const std::size_t steps = (j + b.size() - i) % b.size();
      std::vector<std::uint32_t> run;
      for (std::size_t k = 0; k <= (steps == 0 ? b.size() : steps); ++k) run.push_back(b[(i + k) % b.size()]);
      const auto [l, from] = on_loop.at(run.front());
      const auto [l_to, to] = on_loop.at(run.back());
      if (l != l_to) {
        failure = "the face of max(a, b) joins two boundary curves on the box near " +
                  point_text(positions[run.front()]) + ": creases closer than an edge at the box";
        return std::nullopt;
      }
      const std::vector<std::uint32_t>& loop = loops[l];
      const std::size_t gap = (to + loop.size() - from) % loop.size();
      std::vector<std::uint32_t> side;
      for (std::size_t k = 0; k <= (gap == 0 ? loop.size() : gap); ++k) {
        side.push_back(loop[(from + k) % loop.size()]);
        if (k < (gap == 0 ? loop.size() : gap)) ++covered[l][(from + k) % loop.size()];
      }
      touched[l] = 1;
      zip_between(positions, run, side, out.triangles);
    }
  }
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (!touched[l]) {
      out.free_loops.push_back(loops[l]);
      continue;
    }
    for (std::size_t k = 0; k < loops[l].size(); ++k)
      if (covered[l][k] != 1) {
        failure = "the face of max(a, b) does not close along its boundary on the box near " +
                  point_text(positions[loops[l][k]]) + ": creases closer than an edge at the box";
        return std::nullopt;
      }
  }
  return out;
}

}  // namespace isopatch
