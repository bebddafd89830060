/// \file face_cycles.cpp
/// Boundary cycles of the faces and the splits that make them polygons (face_cycles.hpp).
#include "csg/face_cycles.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace isopatch {

namespace {

/// A curve turning by more than this (radians) is split.
constexpr double kMaxTurn = 0.5 * std::numbers::pi;
/// Every closed loop is split into at least this many curves.
constexpr int kLoopParts = 3;
/// Cycles of fewer sides than this get a side split.
constexpr std::size_t kMinSides = 3;

int face_of(const GraphCurve& c, const HalfCurve& h) {
  return h.reversed ? c.right : c.left;
}

/// The direction a half-curve leaves its start node.
Vec3 leaving(const CreaseGraph& g, const HalfCurve& h) {
  const std::vector<Vec3>& p = g.curves[static_cast<std::size_t>(h.curve)].points;
  const std::size_t n = p.size();
  return h.reversed ? Vec3(p[n - 2] - p[n - 1]) : Vec3(p[1] - p[0]);
}

/// The direction from a half-curve's end node back along it.
Vec3 arriving_back(const CreaseGraph& g, const HalfCurve& h) {
  return leaving(g, {h.curve, !h.reversed});
}

double turning(const std::vector<Vec3>& p) {
  double turn = 0.0;
  for (std::size_t k = 1; k + 1 < p.size(); ++k) {
    const Vec3 a = p[k] - p[k - 1], b = p[k + 1] - p[k];
    turn += std::atan2(a.cross(b).norm(), a.dot(b));
  }
  return turn;
}

std::vector<double> lengths(const std::vector<Vec3>& p) {
  std::vector<double> s(p.size(), 0.0);
  for (std::size_t k = 1; k < p.size(); ++k) s[k] = s[k - 1] + (p[k] - p[k - 1]).norm();
  return s;
}

/// The dense point nearest to arc length `at`, kept strictly inside the curve.
std::size_t index_at(const std::vector<double>& s, double at) {
  const auto it = std::lower_bound(s.begin(), s.end(), at);
  auto k = static_cast<std::size_t>(it - s.begin());
  if (k > 0 && k < s.size() && at - s[k - 1] < s[k] - at) --k;
  return std::clamp<std::size_t>(k, 1, s.size() - 2);
}

}  // namespace

int start_node(const CreaseGraph& g, const HalfCurve& h) {
  const GraphCurve& c = g.curves[static_cast<std::size_t>(h.curve)];
  return h.reversed ? c.end : c.start;
}

int end_node(const CreaseGraph& g, const HalfCurve& h) {
  const GraphCurve& c = g.curves[static_cast<std::size_t>(h.curve)];
  return h.reversed ? c.start : c.end;
}

std::vector<Vec3> half_points(const CreaseGraph& g, const HalfCurve& h) {
  std::vector<Vec3> p = g.curves[static_cast<std::size_t>(h.curve)].points;
  if (h.reversed) std::reverse(p.begin(), p.end());
  return p;
}

std::vector<FaceCycle> face_cycles(const CreaseGraph& g, FaceSet& faces) {
  // The half-curves leaving each node, per face.
  std::map<std::pair<int, int>, std::vector<HalfCurve>> leaving_at;
  std::vector<HalfCurve> all;
  for (std::size_t c = 0; c < g.curves.size(); ++c)
    for (const bool reversed : {false, true}) {
      const HalfCurve h{static_cast<int>(c), reversed};
      all.push_back(h);
      leaving_at[{face_of(g.curves[c], h), start_node(g, h)}].push_back(h);
    }
  std::vector<bool> used(all.size(), false);
  const auto index = [](const HalfCurve& h) {
    return static_cast<std::size_t>(2 * h.curve + (h.reversed ? 1 : 0));
  };
  std::vector<FaceCycle> cycles;
  for (const HalfCurve& first : all) {
    if (used[index(first)]) continue;
    FaceCycle cycle;
    cycle.face = face_of(g.curves[static_cast<std::size_t>(first.curve)], first);
    HalfCurve h = first;
    for (std::size_t guard = 0;; ++guard) {
      if (guard > all.size()) throw CreaseError("the faces of the shape do not close up around a crease");
      used[index(h)] = true;
      cycle.sides.push_back(h);
      const int v = end_node(g, h);
      const std::vector<HalfCurve>& out = leaving_at[{cycle.face, v}];
      if (out.empty())
        throw CreaseError("a crease ends at " + point_text(g.nodes[static_cast<std::size_t>(v)].position) +
                          " where no other crease of its face goes on");
      HalfCurve next = out.front();
      if (out.size() > 1) {
        // The next curve clockwise (about the face's outward normal) from the one arrived along.
        const Vec3 p = g.nodes[static_cast<std::size_t>(v)].position;
        const Vec3 n = faces.function(cycle.face)->value_gradient(p).gradient.normalized();
        const Vec3 e1 = arriving_back(g, h).cross(n).cross(n).normalized() * -1.0;
        const Vec3 e2 = n.cross(e1);
        double best = 3.0 * std::numbers::pi;
        for (const HalfCurve& o : out) {
          if (o.curve == h.curve && o.reversed != h.reversed) continue;  // back along the same curve
          const Vec3 d = leaving(g, o);
          double a = -std::atan2(d.dot(e2), d.dot(e1));  // clockwise angle from the way back
          if (a <= 0.0) a += 2.0 * std::numbers::pi;
          if (a < best) {
            best = a;
            next = o;
          }
        }
      }
      if (next.curve == first.curve && next.reversed == first.reversed) break;
      if (used[index(next)])
        throw ShapeNotManifoldError(
            "the faces around " + point_text(g.nodes[static_cast<std::size_t>(v)].position) +
            " do not close up: the shape is not a 2-manifold there (solids touching along an edge?)");
      h = next;
    }
    cycles.push_back(std::move(cycle));
  }
  return cycles;
}

int split_curve(CreaseGraph& g, std::size_t c, std::size_t index) {
  GraphCurve& curve = g.curves[c];
  const Vec3 p = curve.points[index];
  g.nodes.push_back({p});
  const int node = static_cast<int>(g.nodes.size() - 1);
  GraphCurve rest = curve;
  rest.points.assign(curve.points.begin() + static_cast<std::ptrdiff_t>(index), curve.points.end());
  rest.start = node;
  curve.points.resize(index + 1);
  curve.end = node;
  g.curves.push_back(std::move(rest));
  return node;
}

std::vector<FaceCycle> split_into_polygons(CreaseGraph& g, FaceSet& faces) {
  const std::size_t original = g.curves.size();
  for (std::size_t c = 0; c < original; ++c) {
    const bool closed = g.curves[c].start == g.curves[c].end;
    const int parts = std::max(closed ? kLoopParts : 1,
                               static_cast<int>(std::ceil(turning(g.curves[c].points) / kMaxTurn - 1e-9)));
    if (parts <= 1) continue;
    const std::vector<double> s = lengths(g.curves[c].points);
    if (g.curves[c].points.size() < static_cast<std::size_t>(2 * parts + 1)) continue;
    std::vector<std::size_t> cuts;
    for (int k = 1; k < parts; ++k) cuts.push_back(index_at(s, s.back() * k / parts));
    // From the last cut back, so earlier indices stay valid.
    for (auto it = cuts.rbegin(); it != cuts.rend(); ++it) split_curve(g, c, *it);
  }
  for (int round = 0; round < 64; ++round) {
    std::vector<FaceCycle> cycles = face_cycles(g, faces);
    bool split = false;
    for (const FaceCycle& cycle : cycles) {
      if (cycle.sides.size() >= kMinSides) continue;
      std::size_t longest = 0;
      double best = -1.0;
      for (const HalfCurve& h : cycle.sides) {
        const double l = lengths(g.curves[static_cast<std::size_t>(h.curve)].points).back();
        if (l > best && g.curves[static_cast<std::size_t>(h.curve)].points.size() >= 3) {
          best = l;
          longest = static_cast<std::size_t>(h.curve);
        }
      }
      if (best < 0.0) throw CreaseError("a face of the shape is bounded by curves too short to mesh");
      const std::vector<double> s = lengths(g.curves[longest].points);
      split_curve(g, longest, index_at(s, 0.5 * s.back()));
      split = true;
      break;
    }
    if (!split) return cycles;
  }
  throw CreaseError("a face of the shape could not be cut into polygons");
}

}  // namespace isopatch
