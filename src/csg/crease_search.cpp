/// \file crease_search.cpp
/// Every crease of a CSG shape from seeds on a coarse mesh (crease_search.hpp).
#include "csg/crease_search.hpp"

#include <isopatch/error.hpp>
#include <isopatch/marching_cubes.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "core/point_grid.hpp"
#include "csg/curve_tracer.hpp"
#include "surface/curve_point.hpp"

namespace isopatch {

namespace {

/// Faces whose gradients differ by less than this sine (about 2 degrees) where they meet join without a
/// crease: the sides of a smooth blend.
constexpr double kSmoothSine = 0.035;
/// Faces whose gradients differ by less than this sine where they meet but whose meeting cannot be
/// traced touch tangentially.
constexpr double kContactSine = 0.5;
/// Seeds of one pair of faces tried before it counts as smooth.
constexpr int kSmoothProbes = 4;
/// A seed within this many grid cells of a traced curve of its pair is that curve's.
constexpr double kSeedReach = 1.5;
/// Trace steps are this share of the grid cell.
constexpr double kStepShare = 0.25;
/// How far a seed's Newton point may move, in grid cells.
constexpr double kSeedTravel = 2.0;

/// Points of the traced curves per pair of faces: which seeds are already traced (within `reach`).
class TracedPoints {
 public:
  explicit TracedPoints(double reach) : reach_(reach) {}
  void add(std::pair<int, int> pair, const std::vector<Vec3>& points) {
    Set& s = sets_.try_emplace(pair, reach_).first->second;
    for (const Vec3& p : points) {
      s.grid.insert(p, s.points.size());
      s.points.push_back(p);
    }
  }
  bool near(std::pair<int, int> pair, const Vec3& p) const {
    const auto it = sets_.find(pair);
    if (it == sets_.end()) return false;
    bool hit = false;
    it->second.grid.near(p,
                         [&](std::size_t id) { hit = hit || (it->second.points[id] - p).norm() <= reach_; });
    return hit;
  }

 private:
  struct Set {
    explicit Set(double reach) : grid(reach) {}
    PointGrid grid;
    std::vector<Vec3> points;
  };
  double reach_;
  std::map<std::pair<int, int>, Set> sets_;
};

std::pair<int, int> ordered(int a, int b) {
  return {std::min(a, b), std::max(a, b)};
}

/// The seeds of every pair of faces: midpoints of mesh edges whose ends lie on different faces, in mesh
/// order.
std::map<std::pair<int, int>, std::vector<Vec3>> pair_seeds(const ShapeSamples& s) {
  std::map<std::pair<int, int>, std::vector<Vec3>> seeds;
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (const Triangle& t : s.mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      const int fa = s.face[a], fb = s.face[b];
      if (fa == fb || !seen.emplace(std::min(a, b), std::max(a, b)).second) continue;
      seeds[ordered(fa, fb)].push_back(0.5 * (s.mesh.positions[a] + s.mesh.positions[b]));
    }
  return seeds;
}

}  // namespace

CreaseSearch find_creases(FaceSet& faces, const Box& box, double cell) {
  CreaseSearch out;
  const double longest = (box.hi - box.lo).maxCoeff();
  Settings mc;
  mc.box = box;
  mc.grid = static_cast<int>(std::clamp(std::ceil(longest / cell), 16.0, 128.0));
  out.samples.mesh = marching_cubes(*faces.whole(), mc);
  out.samples.cell = longest / mc.grid;
  const double h = out.samples.cell;
  const double diagonal = box.diagonal();
  const double tolerance = kCreaseTolerance * diagonal;
  // Ties of a switch's operands within this count as both branches taken (a point on a crease).
  const double branch_tolerance = 1e-9 * diagonal;
  for (const Vec3& p : out.samples.mesh.positions) out.samples.face.push_back(faces.face_at(p));

  CurvePointParams seed_params;
  seed_params.tolerance = tolerance;
  seed_params.max_step = h;
  seed_params.max_travel = kSeedTravel * h;
  const Surface& f = *faces.whole();
  // Whether a point of f_i = f_j = 0 is on the shape (f vanishes there too).
  const auto on_shape = [&](const Vec3& p, const Surface& fi) {
    return faces.on_shape(p, fi, kOnShapeTolerances * tolerance);
  };

  // 1. Pairs that meet smoothly (the branches of a smooth blend) are merged.
  {
    const auto seeds = pair_seeds(out.samples);
    for (const auto& [pair, points] : seeds) {
      const Surface& a = *faces.fine_function(pair.first);
      const Surface& b = *faces.fine_function(pair.second);
      bool smooth = true;
      for (std::size_t k = 0; k < points.size() && k < static_cast<std::size_t>(kSmoothProbes) && smooth;
           ++k) {
        const std::optional<Vec3> p = settle_on_curve(a, b, points[k], seed_params);
        const Vec3 q = p && on_shape(*p, a) ? *p : points[k];
        smooth = gradient_sine(a, b, q) < kSmoothSine;
      }
      if (smooth) {
        faces.merge(pair.first, pair.second);
        ++out.smooth_pairs;
      }
    }
    for (int& face : out.samples.face) face = faces.root(face);
  }

  // 2. The creases between the merged faces, traced from their seeds.
  TraceParams trace;
  trace.step = kStepShare * h;
  trace.tolerance = tolerance;
  trace.box = box;
  trace.third_function = [&](int face) -> const Surface& { return *faces.function(face); };
  TracedPoints traced(kSeedReach * h);
  std::deque<std::pair<std::pair<int, int>, Vec3>> work;
  for (const auto& [pair, points] : pair_seeds(out.samples))
    for (const Vec3& p : points) work.emplace_back(pair, p);
  std::set<std::pair<int, int>> traced_pairs;
  std::map<std::pair<int, int>, Vec3> untraced;  // pairs with seeds none of which settled
  std::size_t discovered = 0;
  while (!work.empty()) {
    const auto [pair, seed] = work.front();
    work.pop_front();
    if (traced.near(pair, seed)) continue;
    const Surface& a = *faces.function(pair.first);
    const Surface& b = *faces.function(pair.second);
    const std::optional<Vec3> settled = settle_on_curve(a, b, seed, seed_params);
    if (!settled) {
      if (gradient_sine(a, b, seed) < kContactSine) untraced.emplace(pair, seed);
      continue;
    }
    const Vec3 p = *settled;
    if (traced.near(pair, p)) continue;
    if (!on_shape(p, a)) {
      // Cut away by a third face (one the grid may have missed): seed its pairs here.
      const int third = faces.face_at(p);
      if (third != pair.first && third != pair.second && discovered < 4096) {
        ++discovered;
        work.emplace_back(ordered(pair.first, third), p);
        work.emplace_back(ordered(pair.second, third), p);
      }
      continue;
    }
    const std::array<int, 2> both{pair.first, pair.second};
    if (faces.boundary_face(both, p, branch_tolerance) >= 0)
      continue;  // both functions vanish here, but not as faces of the shape
    if (gradient_sine(a, b, p) < kSmoothSine) {
      untraced.emplace(pair, p);
      continue;
    }
    trace.owner = [&, pair = pair, both = both](const Vec3& q) {
      const auto other = [&](int k) { return k == pair.first || k == pair.second ? -1 : k; };
      if (!on_shape(q, *faces.function(pair.first))) return other(faces.face_at(q));
      // On f = 0 and on both functions, but a face's branches no longer taken: its region ends here.
      return other(faces.boundary_face(both, q, branch_tolerance));
    };
    const TracedPath forward = trace_curve(a, b, p, 1.0, trace);
    TracedPath backward;
    if (forward.end != TraceEnd::Closed) backward = trace_curve(a, b, p, -1.0, trace);
    for (const TracedPath* path : std::array<const TracedPath*, 2>{&forward, &backward}) {
      if (path == &backward && forward.end == TraceEnd::Closed) continue;
      if (path->end == TraceEnd::Box) {
        // The analysis does not cut creases at the box: the caller meshes the shape as a smooth one.
        out.leaves_box = path->points.back();
        return out;
      }
      if (path->end == TraceEnd::Lost)
        throw CreaseError("the crease between two faces cannot be followed near " +
                          point_text(path->points.back()) +
                          " (the faces touch tangentially or the crease has a cusp there)");
    }
    GraphCurve curve;
    curve.first = faces.function(pair.first);
    curve.second = faces.function(pair.second);
    if (forward.end == TraceEnd::Closed) {
      curve.points = forward.points;
      curve.start = curve.end = out.graph.node_at(curve.points.front(), 0.0);
      out.graph.nodes[static_cast<std::size_t>(curve.start)].position = curve.points.front();
    } else {
      curve.points.assign(backward.points.rbegin(), backward.points.rend());
      curve.points.insert(curve.points.end(), forward.points.begin() + 1, forward.points.end());
      const double merge = 1e-9 * diagonal;
      curve.start = out.graph.node_at(curve.points.front(), merge);
      curve.end = out.graph.node_at(curve.points.back(), merge);
      curve.points.front() = out.graph.nodes[static_cast<std::size_t>(curve.start)].position;
      curve.points.back() = out.graph.nodes[static_cast<std::size_t>(curve.end)].position;
      if (curve.start == curve.end)
        throw CreaseError("a crease starts and ends at the same corner near " +
                          point_text(curve.points.front()) + " (the faces meet in a way no mesh can follow)");
    }
    // Which face lies on the left of the curve, seen from outside: probe a little to the left of its
    // middle, on face `first`.
    const std::size_t mid = curve.points.size() / 2;
    const Vec3 m = curve.points[mid];
    const Vec3 t =
        (curve.points[std::min(mid + 1, curve.points.size() - 1)] - curve.points[mid == 0 ? 0 : mid - 1])
            .normalized();
    const ValueGradient ga = a.value_gradient(m);
    const Vec3 left = ga.gradient.normalized().cross(t);
    Vec3 q = m + 1e-4 * h * left;
    const ValueGradient gq = a.value_gradient(q);
    q -= gq.value / gq.gradient.squaredNorm() * gq.gradient;
    // A real point of the face: f changes sign across it (two solids touching along a face give f = 0
    // with f < 0 on both sides there).
    const Vec3 na = gq.gradient.normalized();
    const double across = 1e-7 * h;  // far less than the offset: a face meeting at a small angle is thicker
    const bool first_on_left = on_shape(q, a) && faces.face_at(q) == pair.first &&
                               f.value(q + across * na) > 0.0 && f.value(q - across * na) < 0.0;
    curve.left = first_on_left ? pair.first : pair.second;
    curve.right = first_on_left ? pair.second : pair.first;
    traced.add(pair, curve.points);
    traced_pairs.insert(pair);
    out.graph.curves.push_back(std::move(curve));
  }
  for (const auto& [pair, p] : untraced)
    if (!traced_pairs.count(pair)) out.tangential_contacts.push_back(p);
  return out;
}

}  // namespace isopatch
