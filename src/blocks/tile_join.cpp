// A tile's mesh joined to the loops of its faces' curves in place of its own cut (tile_seam.hpp).
#include <isopatch/error.hpp>

#include "blocks/loop_fill.hpp"
#include "blocks/mesh_cut.hpp"
#include "blocks/tile_seam.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>

namespace isopatch::blocks {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
/// A curve of fewer points than this is filled, not joined to the mesh by a strip.
constexpr std::size_t kShortestStrip = 8;

[[noreturn]] void unjoinable(const std::string& why) {
  throw LimitError("a tile's mesh cannot be joined to its faces' curves (" + why +
                       "): use another number of tiles or a smaller edge",
                   "tiles");
}

/// The boundary loops of the kept triangles of `mesh`, after removing the triangles at every vertex
/// where the kept ones do not make one fan (so that each loop is simple). Updates `kept`.
std::vector<std::vector<std::uint32_t>> simple_boundary_loops(const Mesh& mesh,
                                                              std::vector<std::uint8_t>& kept) {
  const std::size_t n = mesh.vertex_count();
  for (;;) {
    const auto half = directed_edges(mesh, &kept);
    std::vector<std::uint32_t> next(n, kNone);
    std::vector<std::uint8_t> pinched(n, 0);
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      if (!kept[t]) continue;
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t a = mesh.triangles[t][static_cast<std::size_t>(c)];
        const std::uint32_t b = mesh.triangles[t][static_cast<std::size_t>((c + 1) % 3)];
        if (half.count(edge_key(b, a))) continue;
        // The hole lies beyond a -> b; the loop of the remaining mesh runs b <- a, read as a -> b.
        if (next[a] != kNone) pinched[a] = 1;
        next[a] = b;
      }
    }
    bool removed = false;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
      if (kept[t] &&
          (pinched[mesh.triangles[t][0]] || pinched[mesh.triangles[t][1]] || pinched[mesh.triangles[t][2]])) {
        kept[t] = 0;
        removed = true;
      }
    if (removed) continue;
    std::vector<std::vector<std::uint32_t>> loops;
    std::vector<std::uint8_t> seen(n, 0);
    for (std::uint32_t v = 0; v < n; ++v) {
      if (next[v] == kNone || seen[v]) continue;
      std::vector<std::uint32_t> loop;
      for (std::uint32_t w = v; w != kNone && !seen[w]; w = next[w]) {
        seen[w] = 1;
        loop.push_back(w);
      }
      loops.push_back(std::move(loop));
    }
    return loops;
  }
}

/// The points of `loops` in a hash of cells of size `cell`, for the nearest point within a distance.
class LoopPoints {
 public:
  LoopPoints(const std::vector<std::vector<Vec3>>& loops, double cell) : loops_(loops), cell_(cell) {
    for (std::uint32_t l = 0; l < loops.size(); ++l)
      for (std::uint32_t i = 0; i < loops[l].size(); ++i) cells_[cell_of(loops[l][i])].push_back({l, i});
  }
  /// The loop and index of the nearest point within `cell` of p, or {kNone, kNone}.
  std::array<std::uint32_t, 2> nearest(const Vec3& p) const {
    std::array<std::uint32_t, 2> best{kNone, kNone};
    double best_distance = cell_;
    const auto c = cell_of(p);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto found = cells_.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (found == cells_.end()) continue;
          for (const auto& [l, i] : found->second) {
            const double d = (loops_[l][i] - p).norm();
            if (d < best_distance || (d == best_distance && best[0] != kNone && std::array{l, i} < best)) {
              best_distance = d;
              best = {l, i};
            }
          }
        }
    return best;
  }

 private:
  std::array<long, 3> cell_of(const Vec3& p) const {
    return {std::lround(std::floor(p.x() / cell_)), std::lround(std::floor(p.y() / cell_)),
            std::lround(std::floor(p.z() / cell_))};
  }
  const std::vector<std::vector<Vec3>>& loops_;
  double cell_;
  std::map<std::array<long, 3>, std::vector<std::array<std::uint32_t, 2>>> cells_;
};

/// The strip between the mesh's loop `inner` (vertex numbers, in the direction of its boundary edges)
/// and the loop of output numbers `outer` (positions `at`), starting at outer[start]: each step takes the
/// shorter of the two diagonals, unless only the other's triangle faces along grad f (`faces_right`).
/// Triangles oriented as the mesh's.
void zip(const std::vector<std::uint32_t>& inner, const std::vector<std::uint32_t>& outer, std::size_t start,
         const std::vector<Vec3>& at, const std::function<bool(const Triangle&)>& faces_right,
         std::vector<Triangle>& out) {
  const std::size_t ni = inner.size(), no = outer.size();
  std::size_t i = 0, o = 0;
  while (i < ni || o < no) {
    const std::uint32_t a = inner[i % ni], a2 = inner[(i + 1) % ni];
    const std::uint32_t b = outer[(start + o) % no], b2 = outer[(start + o + 1) % no];
    const Triangle along_inner{a2, a, b}, along_outer{a, b, b2};
    bool inner_step = o >= no || (i < ni && (at[a2] - at[b]).norm() <= (at[a] - at[b2]).norm());
    if (i < ni && o < no && !faces_right(inner_step ? along_inner : along_outer) &&
        faces_right(inner_step ? along_outer : along_inner))
      inner_step = !inner_step;
    if (inner_step) {
      out.push_back(along_inner);
      ++i;
    } else {
      out.push_back(along_outer);
      ++o;
    }
  }
}

/// Per triangle: the number of its connected part among the kept triangles (by shared vertices), or
/// kNone for a triangle not kept.
std::vector<std::uint32_t> triangle_parts(const Mesh& mesh, const std::vector<std::uint8_t>& kept) {
  std::vector<std::uint32_t> parent(mesh.vertex_count());
  for (std::uint32_t v = 0; v < parent.size(); ++v) parent[v] = v;
  const auto find = [&](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    if (kept[t])
      for (int c = 1; c < 3; ++c) {
        const std::uint32_t a = find(mesh.triangles[t][0]),
                            b = find(mesh.triangles[t][static_cast<std::size_t>(c)]);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
      }
  std::vector<std::uint32_t> part(mesh.triangle_count(), kNone);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    if (kept[t]) part[t] = find(mesh.triangles[t][0]);
  return part;
}

}  // namespace

namespace {

/// What earlier attempts of join_to_loops() learned, per curve: filled instead of joined, and how many
/// more rings of triangles the mesh loses beside it (a wider gap for a strip that folded).
struct JoinHints {
  std::vector<std::uint8_t> fill;
  std::vector<int> rings;
};

/// Rings of triangles a curve's strip may take away beyond the first, before the curve is filled.
constexpr int kMostRings = 2;

/// One attempt of join_to_loops() with `hints`; returns nothing, with the hints for the curve changed,
/// when a strip to a curve turns away from grad f.
std::optional<Mesh> join_once(const Mesh& mesh, const Surface& surface,
                              const std::vector<std::vector<Vec3>>& loops, double edge, JoinHints& hints) {
  std::vector<std::uint8_t>& fill = hints.fill;
  // The cut: vertices on boundary edges; every triangle at one goes.
  const std::vector<std::uint8_t> on_cut = cut_vertices(mesh);
  std::vector<std::uint8_t> kept(mesh.triangle_count(), 1);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    for (const std::uint32_t v : mesh.triangles[t])
      if (on_cut[v]) kept[t] = 0;
  auto inner = simple_boundary_loops(mesh, kept);

  // A loop of the mesh is nearest the curve whose points are nearest to most of its vertices.
  const LoopPoints points(loops, (3.0 + kMostRings) * edge);
  const auto nearest_of = [&](const std::vector<std::uint32_t>& loop) {
    std::map<std::uint32_t, std::size_t> votes;
    for (const std::uint32_t v : loop) {
      const auto found = points.nearest(mesh.positions[v]);
      if (found[0] != kNone) ++votes[found[0]];
    }
    if (votes.empty()) return kNone;
    return std::max_element(votes.begin(), votes.end(),
                            [](const auto& x, const auto& y) { return x.second < y.second; })
        ->first;
  };
  // The more rings the hints ask for beside a curve.
  for (int ring = 1; ring <= kMostRings; ++ring) {
    std::vector<std::uint8_t> drop(mesh.vertex_count(), 0);
    bool any = false;
    for (const auto& loop : inner) {
      const std::uint32_t l = nearest_of(loop);
      if (l == kNone || hints.rings[l] < ring) continue;
      for (const std::uint32_t v : loop) drop[v] = 1;
      any = true;
    }
    if (!any) break;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
      if (kept[t] && (drop[mesh.triangles[t][0]] || drop[mesh.triangles[t][1]] || drop[mesh.triangles[t][2]]))
        kept[t] = 0;
    inner = simple_boundary_loops(mesh, kept);
  }

  // Each loop of the mesh joins its nearest curve.
  std::vector<std::uint32_t> nearest_curve(inner.size());
  std::vector<std::vector<std::uint32_t>> partners(loops.size());
  for (std::uint32_t m = 0; m < inner.size(); ++m) {
    nearest_curve[m] = nearest_of(inner[m]);
    if (nearest_curve[m] == kNone) unjoinable("a loop of the mesh lies near none of the curves");
    partners[nearest_curve[m]].push_back(m);
  }
  // Where several loops of the mesh are nearest one curve, the part of the mesh inside that curve was
  // cut apart by the band (a piece narrower than two edges); where the curve is short, a strip to it
  // would fold. Either way the parts of the mesh go, when every loop of theirs is nearest that curve, and
  // the curve is filled instead.
  const std::vector<std::uint32_t> part = triangle_parts(mesh, kept);
  std::vector<std::uint32_t> vertex_part(mesh.vertex_count(), kNone);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    if (kept[t])
      for (const std::uint32_t v : mesh.triangles[t]) vertex_part[v] = part[t];
  std::vector<std::uint8_t> large(loops.size(), 0);
  std::map<std::uint32_t, std::size_t> part_vertices;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    if (vertex_part[v] != kNone) ++part_vertices[vertex_part[v]];
  for (std::uint32_t l = 0; l < loops.size(); ++l) {
    if (partners[l].empty()) continue;
    // A part with fewer vertices than its curve has points is a sliver the band nearly took.
    const bool sliver = partners[l].size() == 1 &&
                        part_vertices[vertex_part[inner[partners[l].front()].front()]] < loops[l].size();
    if (partners[l].size() < 2 && loops[l].size() >= kShortestStrip && !fill[l] && !sliver) continue;
    // A part as large as its curve is filled over only by a triangulation facing along grad f (the
    // clean-up then fills it in), never by a fan.
    if (partners[l].size() == 1 && fill[l] && !sliver && loops[l].size() >= kShortestStrip) large[l] = 1;
    std::vector<std::uint32_t> parts;
    // The parts whose every loop is nearest this curve go; a part that also reaches another curve
    // stays, and its loop is joined to this curve (at most one such).
    std::vector<std::uint32_t> staying, going;
    for (const std::uint32_t m : partners[l]) {
      const std::uint32_t p = vertex_part[inner[m].front()];
      bool elsewhere = false;
      for (std::uint32_t n = 0; n < inner.size() && !elsewhere; ++n)
        elsewhere = nearest_curve[n] != l && vertex_part[inner[n].front()] == p;
      (elsewhere ? staying : going).push_back(m);
      if (!elsewhere) parts.push_back(p);
    }
    if (staying.size() > 1) unjoinable("two loops of the mesh lie nearest one curve");
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
      if (kept[t] && std::find(parts.begin(), parts.end(), part[t]) != parts.end()) kept[t] = 0;
    partners[l] = staying;
  }

  // The output: the kept vertices in order, then the loops' points.
  Mesh out;
  std::vector<std::uint32_t> number(mesh.vertex_count(), kNone);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    if (kept[t])
      for (const std::uint32_t v : mesh.triangles[t]) number[v] = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    if (number[v] == 0) {
      number[v] = static_cast<std::uint32_t>(out.positions.size());
      out.positions.push_back(mesh.positions[v]);
    }
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    if (kept[t])
      out.triangles.push_back(
          {number[mesh.triangles[t][0]], number[mesh.triangles[t][1]], number[mesh.triangles[t][2]]});
  std::vector<std::vector<std::uint32_t>> outer(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (const Vec3& p : loops[l]) {
      outer[l].push_back(static_cast<std::uint32_t>(out.positions.size()));
      out.positions.push_back(p);
    }

  // grad f at an output vertex, evaluated once (a strip asks for each vertex in several triangles).
  std::vector<Vec3> gradient;
  std::vector<std::uint8_t> evaluated;
  const auto gradient_at = [&](std::uint32_t v) -> const Vec3& {
    if (v >= gradient.size()) {
      gradient.resize(out.positions.size());
      evaluated.resize(out.positions.size(), 0);
    }
    if (!evaluated[v]) {
      gradient[v] = surface.value_gradient(out.positions[v]).gradient;
      evaluated[v] = 1;
    }
    return gradient[v];
  };
  for (std::uint32_t l = 0; l < loops.size(); ++l) {
    std::vector<std::uint32_t>& o = outer[l];
    if (o.size() < 3 && partners[l].empty()) unjoinable("a curve of fewer than three points");
    if (!partners[l].empty()) {
      std::vector<std::uint32_t> in;
      for (const std::uint32_t v : inner[partners[l].front()]) in.push_back(number[v]);
      // The curve runs the way the mesh's loop runs: the tangents at nearest points agree on the whole.
      double agreement = 0.0;
      const std::size_t ni = in.size(), no = o.size();
      const auto nearest_on = [&](const Vec3& p) {
        std::size_t best = 0;
        for (std::size_t j = 1; j < no; ++j)
          if ((out.positions[o[j]] - p).squaredNorm() < (out.positions[o[best]] - p).squaredNorm()) best = j;
        return best;
      };
      for (std::size_t i = 0; i < ni; ++i) {
        const Vec3 t_in = out.positions[in[(i + 1) % ni]] - out.positions[in[(i + ni - 1) % ni]];
        const std::size_t j = nearest_on(out.positions[in[i]]);
        const Vec3 t_out = out.positions[o[(j + 1) % no]] - out.positions[o[(j + no - 1) % no]];
        agreement += t_in.dot(t_out);
      }
      if (agreement < 0.0) std::reverse(o.begin(), o.end());
      const std::size_t first = out.triangles.size();
      const auto faces_right = [&](const Triangle& t) {
        return faces_along(out.positions[t[0]], out.positions[t[1]], out.positions[t[2]],
                           {gradient_at(t[0]), gradient_at(t[1]), gradient_at(t[2])});
      };
      zip(in, o, nearest_on(out.positions[in[0]]), out.positions, faces_right, out.triangles);
      for (std::size_t t = first; t < out.triangles.size(); ++t) {
        if (!faces_right(out.triangles[t])) {
          // The strip folds: the next attempt leaves a wider gap beside the curve, or fills it.
          if (hints.rings[l] < kMostRings)
            ++hints.rings[l];
          else
            fill[l] = 1;
          return std::nullopt;
        }
      }
    } else {
      // No part of the mesh beside this curve (or none left).
      if (!fill_loop(surface, o, out) && large[l]) unjoinable("the strip to a curve folds");
    }
  }
  // Every edge in at most two triangles, oppositely: else the strips folded (curves too close).
  std::unordered_map<std::uint64_t, std::uint32_t> used;
  for (const Triangle& t : out.triangles)
    for (int c = 0; c < 3; ++c)
      if (used[edge_key(t[static_cast<std::size_t>(c)], t[static_cast<std::size_t>((c + 1) % 3)])]++ > 0)
        unjoinable("the strips to the curves fold over");
  return out;
}

}  // namespace

Mesh join_to_loops(const Mesh& mesh, const Surface& surface, const std::vector<std::vector<Vec3>>& loops,
                   double edge) {
  JoinHints hints{std::vector<std::uint8_t>(loops.size(), 0), std::vector<int>(loops.size(), 0)};
  for (std::size_t attempt = 0; attempt <= loops.size() * (kMostRings + 1); ++attempt)
    if (auto joined = join_once(mesh, surface, loops, edge, hints)) return std::move(*joined);
  unjoinable("every strip folds");
}

}  // namespace isopatch::blocks
