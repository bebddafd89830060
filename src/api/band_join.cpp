// The band between a trimmed face and its crease loops (band_join.hpp).
#include "api/band_join.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <unordered_map>

#include "core/point_grid.hpp"
#include "csg/crease_graph.hpp"

namespace isopatch {

void zip_chains(const std::vector<Vec3>& x, const std::vector<std::uint32_t>& p,
                const std::vector<std::uint32_t>& q, std::vector<Triangle>& out) {
  std::size_t i = 0, j = 0;
  while (i + 1 < p.size() || j + 1 < q.size()) {
    const bool advance_p = j + 1 == q.size() || (i + 1 < p.size() && (x[p[i + 1]] - x[q[j]]).norm() <=
                                                                         (x[q[j + 1]] - x[p[i]]).norm());
    if (advance_p) {
      out.push_back({p[i + 1], p[i], q[j]});
      ++i;
    } else {
      out.push_back({q[j], q[j + 1], p[i]});
      ++j;
    }
  }
}

void zip_between(const std::vector<Vec3>& x, const std::vector<std::uint32_t>& p,
                 const std::vector<std::uint32_t>& q, std::vector<Triangle>& out) {
  const std::size_t n = p.size(), m = q.size();
  if (n < 2 || m < 2 || (n == 2 && m == 2)) return;
  if (m == 2) {
    for (std::size_t k = 0; k + 2 < n; ++k) out.push_back({p[k + 1], p[k], p.back()});
    return;
  }
  if (n == 2) {
    for (std::size_t k = 1; k + 1 < m; ++k) out.push_back({q[k], q[k + 1], p.front()});
    return;
  }
  out.push_back({p[1], p[0], q[1]});
  zip_chains(x, std::vector<std::uint32_t>(p.begin() + 1, p.end() - 1),
             std::vector<std::uint32_t>(q.begin() + 1, q.end() - 1), out);
  out.push_back({q[m - 2], q[m - 1], p[n - 2]});
}

namespace {

/// A boundary vertex looks for its crease within this many edges.
constexpr double kBandReach = 3.0;
/// A walk's next crease point lies along the arc (not across a neck) when the arc to it is at most this
/// many times the straight way there plus kArcSlack edges; one at most kNoiseSteps behind is noise.
constexpr double kArcToChord = 2.0;
constexpr double kArcSlack = 2.5;
constexpr std::size_t kNoiseSteps = 2;
/// At most this many boundary vertices in a row nearest to another crease count as noise.
constexpr std::size_t kNoiseVertices = 2;
/// Two crease loops with no walk beside them are the sides of a strip when this share of each one's
/// points lies nearest to the other.
constexpr double kStripShare = 0.9;
/// A neck bounded by more arcs than this is refused.
constexpr std::size_t kMostNeckArcs = 6;

/// The nearest crease point within a few edges (core/point_grid.hpp, cubes of the reach).
class CreaseGrid {
 public:
  CreaseGrid(const std::vector<Vec3>& points, const std::vector<std::vector<std::uint32_t>>& loops,
             double cell)
      : points_(points), grid_(cell) {
    for (const std::vector<std::uint32_t>& loop : loops)
      for (std::uint32_t k : loop) grid_.insert(points[k], k);
  }

  /// The nearest point within `reach` (at most the cube's side) of p for which `skip` is false, or -1
  /// (ties: the smaller id, whatever the order of the visit).
  template <class Skip>
  std::int64_t nearest(const Vec3& p, double reach, Skip skip) const {
    std::int64_t best = -1;
    double best_distance = reach;
    grid_.near(p, [&](std::size_t id) {
      const auto k = static_cast<std::uint32_t>(id);
      if (skip(k)) return;
      const double d = (points_[k] - p).norm();
      if (d < best_distance || (d == best_distance && best >= 0 && k < best)) {
        best_distance = d;
        best = k;
      }
    });
    return best;
  }

 private:
  const std::vector<Vec3>& points_;
  PointGrid grid_;
};

/// A place on a crease loop: the loop and the index along it (the face's direction).
struct Place {
  std::int64_t loop = -1;
  std::size_t index = 0;
};

/// A crease arc a walk passed: from `start` on, `length` edges; entered across a bridge from `from`
/// (or at the walk's start: loop -1) and left across one to `to` (or not at all: loop -1).
struct Run {
  std::size_t start = 0, length = 0;
  Place from, to;
};

/// `loop` from index `from`, `steps` edges forward (steps + 1 ids).
std::vector<std::uint32_t> arc(const std::vector<std::uint32_t>& loop, std::size_t from, std::size_t steps) {
  std::vector<std::uint32_t> out;
  for (std::size_t k = 0; k <= steps; ++k) out.push_back(loop[(from + k) % loop.size()]);
  return out;
}

class BandJoiner {
 public:
  BandJoiner(const BandJoinInput& in, std::string& failure)
      : in_(in), failure_(failure), grid_(in.positions, in.crease, kBandReach * in.edge) {
    for (std::size_t c = 0; c < in.crease.size(); ++c)
      for (std::size_t k = 0; k < in.crease[c].size(); ++k)
        place_[in.crease[c][k]] = {static_cast<std::int64_t>(c), k};
    runs_.resize(in.crease.size());
    used_.resize(in.crease.size());
    for (std::size_t c = 0; c < in.crease.size(); ++c) used_[c].assign(in.crease[c].size(), 0);
  }

  std::optional<BandJoin> run() {
    for (const std::vector<std::uint32_t>& loop : in_.boundary)
      if (!walk(loop)) return std::nullopt;
    BandJoin out;
    out.untouched.assign(in_.crease.size(), 0);
    for (std::size_t c = 0; c < in_.crease.size(); ++c) {
      out.untouched[c] = runs_[c].empty() ? 1 : 0;
    }
    if (!join_necks()) return std::nullopt;
    join_strips(out.untouched);
    for (std::size_t c = 0; c < in_.crease.size(); ++c) {
      if (out.untouched[c]) continue;
      for (std::uint8_t u : used_[c])
        if (u != 1) {
          failure_ = "the face of max(a, b) does not close along its crease near " +
                     point_text(in_.positions[in_.crease[c].front()]) + ": creases closer than an edge";
          return std::nullopt;
        }
    }
    out.triangles = std::move(triangles_);
    out.extra = std::move(extra_);
    return out;
  }

 private:
  std::size_t size(std::int64_t loop) const { return in_.crease[static_cast<std::size_t>(loop)].size(); }
  std::uint32_t id(const Place& p) const {
    return in_.crease[static_cast<std::size_t>(p.loop)][p.index % size(p.loop)];
  }
  const Vec3& at(std::uint32_t v) const { return in_.positions[v]; }

  void use(std::int64_t loop, std::size_t index) {
    ++used_[static_cast<std::size_t>(loop)][index % size(loop)];
  }

  /// Walks one boundary loop of the trimmed face along the creases beside it.
  bool walk(const std::vector<std::uint32_t>& p) {
    const std::size_t n = p.size();
    std::vector<Place> near(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t k =
          grid_.nearest(at(p[i]), kBandReach * in_.edge, [](std::uint32_t) { return false; });
      if (k < 0) {
        failure_ = "the face of max(a, b) has a boundary with no crease beside it near " +
                   point_text(at(p[i])) + ": a feature narrower than an edge";
        return false;
      }
      near[i] = place_.at(static_cast<std::uint32_t>(k));
    }
    // A vertex or two nearest to a crease that neither neighbour is nearest to are noise (a crease passing
    // close by): they take their nearest point on the crease before them.
    for (std::size_t length = 1; length <= kNoiseVertices; ++length)
      for (std::size_t i = 0; i < n && n > length + 1; ++i) {
        const Place before = near[(i + n - 1) % n];
        const Place after = near[(i + length) % n];
        const std::int64_t loop = near[i].loop;
        bool other = loop != before.loop && loop != after.loop;
        for (std::size_t k = 1; k < length && other; ++k) other = near[(i + k) % n].loop == loop;
        if (!other) continue;
        for (std::size_t k = 0; k < length; ++k) {
          const std::int64_t q =
              grid_.nearest(at(p[(i + k) % n]), kBandReach * in_.edge,
                            [&](std::uint32_t w) { return place_.at(w).loop != before.loop; });
          if (q >= 0) near[(i + k) % n] = place_.at(static_cast<std::uint32_t>(q));
        }
      }
    std::vector<Run> walked{Run{near[0].index, 0, {}, {}}};
    std::vector<std::int64_t> walked_loop{near[0].loop};
    Place state = near[0];
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t a = p[i], b = p[(i + 1) % n];
      const Place target = near[(i + 1) % n];
      const std::size_t m = size(state.loop);
      const std::size_t forward = (target.index + m - state.index) % m;
      const std::size_t back = (state.index + m - target.index) % m;
      // Along the same arc when the arc to the target is about as long as the way there (a nearest point
      // slightly behind is noise: no step back); else a jump across a neck of this crease.
      const double chord = (at(id(target)) - at(id(state))).norm();
      const bool along =
          static_cast<double>(forward) * in_.edge <= kArcToChord * chord + kArcSlack * in_.edge;
      if (target.loop == state.loop && (along || back <= kNoiseSteps)) {
        // Along the same arc (a nearest point slightly behind is noise: no step back).
        std::size_t steps = along ? forward : 0;
        bool moved_p = false;
        while (true) {
          const std::uint32_t q = id(state), q_next = id({state.loop, state.index + 1});
          if (!moved_p && (steps == 0 || (at(b) - at(q)).norm() <= (at(q_next) - at(a)).norm())) {
            triangles_.push_back({b, a, q});
            moved_p = true;
          }
          if (steps == 0) break;
          triangles_.push_back({q, q_next, moved_p ? b : a});
          use(state.loop, state.index);
          ++walked.back().length;
          state.index = (state.index + 1) % m;
          --steps;
        }
        continue;
      }
      // A bridge to another crease, or across a neck to another part of this one.
      triangles_.push_back({b, a, id(state)});
      triangles_.push_back({id(state), id(target), b});
      walked.back().to = target;
      walked.push_back(Run{target.index, 0, state, {}});
      walked_loop.push_back(target.loop);
      state = target;
    }
    // The last run (after the last bridge, or the whole walk) goes on into the first: the walk is a loop.
    if (walked.size() > 1) {
      if (walked_loop.back() != walked_loop.front()) {
        failure_ = "the face of max(a, b) has a boundary that does not follow its crease near " +
                   point_text(at(p[0])) + ": creases closer than an edge";
        return false;
      }
      walked.front().start = walked.back().start;
      walked.front().length += walked.back().length;
      walked.front().from = walked.back().from;
      walked.pop_back();
      walked_loop.pop_back();
    }
    for (std::size_t r = 0; r < walked.size(); ++r)
      runs_[static_cast<std::size_t>(walked_loop[r])].push_back(walked[r]);
    return true;
  }

  /// Joins the necks: the crease arcs between one run's end and the next run's start on each loop. Each
  /// neck is a cycle of such arcs linked by the bridges that left them: one arc (a bay its own bridge
  /// closes: a fan) or two facing arcs (chain to chain), three or more (where strips branch: a fan from a
  /// new point at their centroid).
  bool join_necks() {
    for (std::size_t c = 0; c < in_.crease.size(); ++c) {
      std::vector<Run>& runs = runs_[c];
      std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.start < b.start; });
      for (const Run& run : runs)
        if (run.to.loop < 0 && (runs.size() != 1 || run.length != in_.crease[c].size()))
          return refuse(c, run.start);
    }
    std::map<std::pair<std::int64_t, std::size_t>, std::size_t> run_ending;  // (loop, end index) -> run
    for (std::size_t c = 0; c < in_.crease.size(); ++c)
      for (std::size_t r = 0; r < runs_[c].size(); ++r) {
        const Run& run = runs_[c][r];
        if (run.to.loop >= 0) run_ending[{static_cast<std::int64_t>(c), end_of(c, run)}] = r;
      }
    std::vector<std::vector<std::uint8_t>> done(in_.crease.size());
    for (std::size_t c = 0; c < in_.crease.size(); ++c) done[c].assign(runs_[c].size(), 0);
    for (std::size_t c = 0; c < in_.crease.size(); ++c)
      for (std::size_t r = 0; r < runs_[c].size(); ++r) {
        if (done[c][r] || runs_[c][r].to.loop < 0) continue;
        // The cycle of arcs from this run's end.
        std::vector<std::vector<std::uint32_t>> arcs;
        std::size_t loop = c, run = r;
        while (true) {
          done[loop][run] = 1;
          const std::vector<Run>& on = runs_[loop];
          const Run& next = on[(run + 1) % on.size()];
          const std::size_t m = in_.crease[loop].size(), end = end_of(loop, on[run]);
          const std::size_t gap = (next.start + m - end) % m;
          if (on.size() > 1 && 2 * gap > m) return refuse(loop, end);  // the runs overlap
          arcs.push_back(arc(in_.crease[loop], end, gap));
          for (std::size_t k = 0; k < gap; ++k) use(static_cast<std::int64_t>(loop), end + k);
          const auto from = run_ending.find({next.from.loop, next.from.index});
          if (next.from.loop < 0 || from == run_ending.end() || arcs.size() > kMostNeckArcs)
            return refuse(loop, end);
          loop = static_cast<std::size_t>(next.from.loop);
          run = from->second;
          if (loop == c && run == r) break;
          if (done[loop][run]) return refuse(loop, end);
        }
        join_neck(arcs);
      }
    return true;
  }

  std::size_t end_of(std::size_t c, const Run& run) const {
    return (run.start + run.length) % in_.crease[c].size();
  }

  /// Triangles over one neck bounded by `arcs` (each along its crease, the neck on its left; the last
  /// point of each bridged to the first of the next).
  void join_neck(const std::vector<std::vector<std::uint32_t>>& arcs) {
    if (arcs.size() == 2) {
      std::vector<std::uint32_t> side = arcs[0];
      std::reverse(side.begin(), side.end());
      zip_chains(in_.positions, side, arcs[1], triangles_);
      return;
    }
    Vec3 centre = Vec3::Zero();
    std::size_t count = 0;
    for (const auto& a : arcs)
      for (std::uint32_t v : a) centre += at(v), ++count;
    const auto middle = static_cast<std::uint32_t>(in_.positions.size() + extra_.size());
    extra_.push_back(centre / static_cast<double>(count));
    for (std::size_t i = 0; i < arcs.size(); ++i) {
      const std::vector<std::uint32_t>& a = arcs[i];
      for (std::size_t k = 0; k + 1 < a.size(); ++k) triangles_.push_back({a[k], a[k + 1], middle});
      const std::uint32_t first_next = arcs[(i + 1) % arcs.size()].front();
      if (first_next != a.back()) triangles_.push_back({a.back(), first_next, middle});
    }
  }

  bool refuse(std::size_t c, std::size_t index) {
    failure_ = "the face of max(a, b) meets its crease in a knot of necks near " +
               point_text(in_.positions[in_.crease[c][index % in_.crease[c].size()]]) +
               ": creases closer than an edge";
    return false;
  }

  /// Crease loops no walk reached, in pairs whose points lie nearest to each other: the two sides of a
  /// strip narrower than the trim, joined side to side; they leave `untouched`.
  void join_strips(std::vector<std::uint8_t>& untouched) {
    std::vector<std::int64_t> best(in_.crease.size(), -1);
    for (std::size_t c = 0; c < in_.crease.size(); ++c) {
      if (!untouched[c]) continue;
      std::map<std::int64_t, std::size_t> votes;
      for (std::uint32_t v : in_.crease[c]) {
        const std::int64_t k = grid_.nearest(at(v), kBandReach * in_.edge, [&](std::uint32_t w) {
          const Place& pw = place_.at(w);
          return pw.loop == static_cast<std::int64_t>(c) || !untouched[static_cast<std::size_t>(pw.loop)];
        });
        if (k >= 0) ++votes[place_.at(static_cast<std::uint32_t>(k)).loop];
      }
      for (const auto& [loop, count] : votes)
        if (static_cast<double>(count) >= kStripShare * static_cast<double>(in_.crease[c].size()))
          best[c] = loop;
    }
    for (std::size_t c = 0; c < in_.crease.size(); ++c) {
      const std::int64_t o = best[c];
      if (o <= static_cast<std::int64_t>(c) ||
          best[static_cast<std::size_t>(o)] != static_cast<std::int64_t>(c))
        continue;
      // This loop turned to have the strip on its right, closed, to the other from its nearest point.
      const std::vector<std::uint32_t>& mine = in_.crease[c];
      std::vector<std::uint32_t> side(mine.rbegin(), mine.rend());
      side.push_back(side.front());
      const std::int64_t k = grid_.nearest(at(side.front()), kBandReach * in_.edge,
                                           [&](std::uint32_t w) { return place_.at(w).loop != o; });
      const std::size_t start = k >= 0 ? place_.at(static_cast<std::uint32_t>(k)).index : 0;
      zip_chains(in_.positions, side, arc(in_.crease[static_cast<std::size_t>(o)], start, size(o)),
                 triangles_);
      untouched[c] = untouched[static_cast<std::size_t>(o)] = 0;
      std::fill(used_[c].begin(), used_[c].end(), 1);
      std::fill(used_[static_cast<std::size_t>(o)].begin(), used_[static_cast<std::size_t>(o)].end(), 1);
    }
  }

  const BandJoinInput& in_;
  std::string& failure_;
  CreaseGrid grid_;
  std::unordered_map<std::uint32_t, Place> place_;
  std::vector<std::vector<Run>> runs_;
  std::vector<std::vector<std::uint8_t>> used_;
  std::vector<Triangle> triangles_;
  std::vector<Vec3> extra_;
};

}  // namespace

std::optional<BandJoin> join_band(const BandJoinInput& in, std::string& failure) {
  return BandJoiner(in, failure).run();
}

}  // namespace isopatch
