/// \file crease_search.cpp
/// Every crease of a CSG shape from seeds on a coarse mesh, certified by the interval cover
/// (crease_search.hpp).
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
#include "surface/project_point.hpp"
#include "surface/sampler.hpp"

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
/// The interval cover's finest cells are this share of the grid cell (so a crease through one passes
/// within kSeedReach cells of its centre).
constexpr double kCoverLeaf = 0.5;
/// A face beside a crease is probed this share of the grid cell off the crease, and its change of sign
/// tested this share of the grid cell across it (far less: a face meeting at a small angle is thicker).
constexpr double kProbeShare = 1e-4;
constexpr double kAcrossShare = 1e-7;
/// Pairs seeded from points cut away by a third face, at most.
constexpr std::size_t kMaxDiscoveries = 4096;

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

/// What became of one seed.
enum class SeedOutcome {
  Known,      ///< on a crease already traced
  Traced,     ///< a new crease traced from it
  Unsettled,  ///< Newton found no point of both functions near it
  Flush,      ///< the two functions vanish together on a surface there (coincident faces, a sheet)
  Touch,      ///< the two faces touch there with nearly parallel gradients and do not cross
  Met,        ///< near a place where the pair was already found flush or touching
  CutAway,    ///< its point is cut away by a third face (whose pairs were seeded)
  NotFaces,   ///< both functions vanish there, but not as faces of the shape
  Smooth,     ///< the faces meet there without a crease
};

/// The search's state: the faces, the traced creases, the queue of seeds.
class Search {
 public:
  Search(FaceSet& faces, const Box& box, CreaseSearch& out, std::size_t cover_budget)
      : faces_(faces),
        box_(box),
        out_(out),
        cover_budget_(cover_budget),
        h_(out.samples.cell),
        traced_(kSeedReach * out.samples.cell),
        met_(kSeedReach * out.samples.cell) {
    const double tolerance = kCreaseTolerance * box.diagonal();
    branch_tolerance_ = 1e-9 * box.diagonal();  // operands this close count as both branches taken
    on_shape_tolerance_ = kOnShapeTolerances * tolerance;
    seed_params_.tolerance = tolerance;
    seed_params_.max_step = h_;
    seed_params_.max_travel = kSeedTravel * h_;
    trace_.step = kStepShare * h_;
    trace_.tolerance = tolerance;
    trace_.box = box;
    trace_.third_function = [this](int face) -> const Surface& { return *faces_.function(face); };
  }

  /// 1. Pairs that meet smoothly (the branches of a smooth blend) are merged.
  void merge_smooth_pairs() {
    for (const auto& [pair, points] : pair_seeds(out_.samples)) {
      const Surface& a = *faces_.fine_function(pair.first);
      const Surface& b = *faces_.fine_function(pair.second);
      bool smooth = true;
      for (std::size_t k = 0; k < points.size() && k < static_cast<std::size_t>(kSmoothProbes) && smooth;
           ++k) {
        const std::optional<Vec3> p = settle_on_curve(a, b, points[k], seed_params_);
        const Vec3 q = p && on_shape(*p, a) ? *p : points[k];
        smooth = gradient_sine(a, b, q) < kSmoothSine;
      }
      if (smooth) {
        faces_.merge(pair.first, pair.second);
        ++out_.smooth_pairs;
      }
    }
    for (int& face : out_.samples.face) face = faces_.root(face);
  }

  /// 2. The creases between the merged faces, traced from the grid's seeds. False when a crease leaves
  /// the box (out.leaves_box says where).
  bool trace_grid_seeds() {
    for (const auto& [pair, points] : pair_seeds(out_.samples))
      for (const Vec3& p : points) work_.emplace_back(pair, p);
    return drain();
  }

  /// 3. Every finest cell of the interval cover explained: a traced crease of each of its pairs passes
  /// near, or a seed at its centre traces a new one, finds the faces meeting smoothly or not as faces of
  /// the shape, or intervals show one of the two functions cannot vanish in it. False when a crease
  /// leaves the box.
  bool certify() {
    const std::size_t before = out_.graph.curves.size();
    const CreaseCover cover = crease_cover(faces_, box_, kCoverLeaf * h_, cover_budget_);
    CreaseCertificate& c = out_.certificate;
    c.examined = cover.examined;
    c.cells = cover.cells.size();
    c.uncertain = cover.over_budget;
    for (const CreaseCell& cell : cover.cells) {
      const Vec3 centre = cell.box.centre();
      bool explained = true;
      for (const std::pair<int, int>& pair : cell.pairs) {
        if (traced_.near(pair, centre)) continue;
        const SeedOutcome outcome = process(pair, centre, true);
        if (!drain()) return false;
        if (outcome == SeedOutcome::Flush || outcome == SeedOutcome::Touch || outcome == SeedOutcome::Met)
          ++c.touching;
        if (outcome != SeedOutcome::Unsettled && outcome != SeedOutcome::CutAway) continue;
        if (cannot_vanish(*faces_.function(pair.first), cell.box) ||
            cannot_vanish(*faces_.function(pair.second), cell.box))
          continue;
        explained = false;
      }
      if (!explained && c.uncertain++ == 0) c.first_uncertain = centre;
    }
    c.found = out_.graph.curves.size() - before;
    return true;
  }

  /// Pairs seen meeting smoothly where nothing of them was traced: tangential contacts.
  void report_contacts() {
    for (const auto& [pair, p] : untraced_)
      if (!traced_pairs_.count(pair)) out_.tangential_contacts.push_back(p);
  }

 private:
  FaceSet& faces_;
  Box box_;
  CreaseSearch& out_;
  std::size_t cover_budget_;
  double h_;
  double branch_tolerance_ = 0.0;
  double on_shape_tolerance_ = 0.0;
  CurvePointParams seed_params_;
  TraceParams trace_;
  TracedPoints traced_;
  TracedPoints met_;  // points where a pair's faces were found lying on one another or touching
  std::deque<std::pair<std::pair<int, int>, Vec3>> work_;
  std::set<std::pair<int, int>> traced_pairs_;
  std::map<std::pair<int, int>, Vec3> untraced_;  // pairs with seeds none of which settled
  std::size_t discovered_ = 0;

  /// Whether a point of f_i = f_j = 0 is on the shape (f vanishes there too).
  bool on_shape(const Vec3& p, const Surface& fi) const {
    return faces_.on_shape(p, fi, on_shape_tolerance_);
  }

  /// Whether the two functions vanish together on a surface near `seed` (coincident faces: the shared
  /// face of two solids put side by side, or two flush faces): the point of a on the way to it is on b
  /// too, with parallel gradients.
  bool flush(const Surface& a, const Surface& b, const Vec3& seed) const {
    Vec3 q = seed;
    if (!project_to_surface(Sampler(a), q, seed_params_.tolerance, h_) ||
        (q - seed).norm() > kSeedTravel * h_)
      return false;
    const ValueGradient gb = b.value_gradient(q);
    return std::abs(gb.value) <= kOnShapeTolerances * seed_params_.tolerance * gb.gradient.norm() &&
           gradient_sine(a, b, q) < kSmoothSine;
  }

  /// Whether `face` (function g; `other` the function of the face across) is a face of the solid beside
  /// the crease point p: a point of g = 0 a little way off the crease, on one side or the other, lies
  /// where f takes the face's branches and f changes sign across it. False for a face f only touches
  /// at p (branches tied there but taken nowhere near) and for a sheet inside the solid or outside it
  /// (f = 0 without a change of sign: the shared face of two solids put side by side).
  bool real_face(int face, const Surface& g, const Surface& other, const Vec3& p) {
    const Vec3 n = g.value_gradient(p).gradient.normalized();
    const Vec3 along = n.cross(other.value_gradient(p).gradient).cross(n).normalized();
    return face_beside(face, g, p, along) || face_beside(face, g, p, -along);
  }

  /// Whether `face` (function g) is a face of the solid at the point of g = 0 nearest to a step of a
  /// probe share of the grid cell from p along `direction` (unit): f takes the face's branches there and
  /// changes sign across it (two solids touching along a face give f = 0 with f < 0 on both sides).
  bool face_beside(int face, const Surface& g, const Vec3& p, const Vec3& direction) {
    Vec3 q = p + kProbeShare * h_ * direction;
    if (!project_to_surface(Sampler(g), q, seed_params_.tolerance, h_)) return false;
    const Vec3 nq = g.value_gradient(q).gradient.normalized();
    const double across = kAcrossShare * h_;
    const Surface& f = *faces_.whole();
    return faces_.face_at(q) == face && f.value(q + across * nq) > 0.0 && f.value(q - across * nq) < 0.0;
  }

  /// Whether intervals prove g has no zero in the cell (none when g has no interval evaluator).
  static bool cannot_vanish(const Surface& g, const Box& cell) {
    const std::optional<Interval> range = g.bound(cell);
    return range && range->excludes_zero();
  }

  /// Runs the queued seeds. False when a crease leaves the box.
  bool drain() {
    while (!work_.empty()) {
      const auto [pair, seed] = work_.front();
      work_.pop_front();
      process(pair, seed, false);
    }
    return !out_.leaves_box.has_value();
  }

  /// One seed of a pair of faces: put on both functions and, when it is a crease point not yet traced,
  /// the crease traced through it. A seed from the cover that meets no crease is not a contact.
  SeedOutcome process(std::pair<int, int> pair, const Vec3& seed, bool from_cover) {
    if (traced_.near(pair, seed)) return SeedOutcome::Known;
    if (from_cover && met_.near(pair, seed)) return SeedOutcome::Met;
    const Surface& a = *faces_.function(pair.first);
    const Surface& b = *faces_.function(pair.second);
    const std::optional<Vec3> settled = settle_on_curve(a, b, seed, seed_params_);
    if (!settled) {
      if (from_cover) {
        // Without a crossing near: the faces lie on one another or touch at a point (a box face
        // tangent to a sphere the box holds), which no crease follows.
        const SeedOutcome o = flush(a, b, seed)                          ? SeedOutcome::Flush
                              : gradient_sine(a, b, seed) < kContactSine ? SeedOutcome::Touch
                                                                         : SeedOutcome::Unsettled;
        if (o != SeedOutcome::Unsettled) met_.add(pair, {seed});
        return o;
      }
      if (gradient_sine(a, b, seed) < kContactSine) untraced_.emplace(pair, seed);
      return SeedOutcome::Unsettled;
    }
    const Vec3 p = *settled;
    if (traced_.near(pair, p)) return SeedOutcome::Known;
    if (!on_shape(p, a)) {
      // Cut away by a third face (one the grid may have missed): seed its pairs here.
      const int third = faces_.face_at(p);
      if (third != pair.first && third != pair.second && discovered_ < kMaxDiscoveries) {
        ++discovered_;
        work_.emplace_back(ordered(pair.first, third), p);
        work_.emplace_back(ordered(pair.second, third), p);
      }
      return SeedOutcome::CutAway;
    }
    const std::array<int, 2> both{pair.first, pair.second};
    if (faces_.boundary_face(both, p, branch_tolerance_) >= 0 || !real_face(pair.first, a, b, p) ||
        !real_face(pair.second, b, a, p))
      return SeedOutcome::NotFaces;
    if (gradient_sine(a, b, p) < kSmoothSine) {
      if (!from_cover) untraced_.emplace(pair, p);
      return SeedOutcome::Smooth;
    }
    trace_.owner = [&, pair, both](const Vec3& q) {
      const auto other = [&](int k) { return k == pair.first || k == pair.second ? -1 : k; };
      if (!on_shape(q, *faces_.function(pair.first))) return other(faces_.face_at(q));
      // On f = 0 and on both functions, but a face's branches no longer taken: its region ends here.
      return other(faces_.boundary_face(both, q, branch_tolerance_));
    };
    const TracedPath forward = trace_curve(a, b, p, 1.0, trace_);
    TracedPath backward;
    if (forward.end != TraceEnd::Closed) backward = trace_curve(a, b, p, -1.0, trace_);
    for (const TracedPath* path : std::array<const TracedPath*, 2>{&forward, &backward}) {
      if (path == &backward && forward.end == TraceEnd::Closed) continue;
      if (path->end == TraceEnd::Box) {
        // The analysis does not cut creases at the box: the caller meshes the shape as a smooth one.
        out_.leaves_box = path->points.back();
        work_.clear();
        return SeedOutcome::Traced;
      }
      if (path->end == TraceEnd::Lost)
        throw CreaseError("the crease between two faces cannot be followed near " +
                          point_text(path->points.back()) +
                          " (the faces touch tangentially or the crease has a cusp there)");
    }
    GraphCurve curve = make_curve(pair, forward, backward);
    traced_.add(pair, curve.points);
    traced_pairs_.insert(pair);
    out_.graph.curves.push_back(std::move(curve));
    return SeedOutcome::Traced;
  }

  /// The graph curve of a traced crease: its points joined to the graph's nodes, its faces sided.
  GraphCurve make_curve(std::pair<int, int> pair, const TracedPath& forward, const TracedPath& backward) {
    const Surface& a = *faces_.function(pair.first);
    GraphCurve curve;
    curve.first = faces_.function(pair.first);
    curve.second = faces_.function(pair.second);
    CreaseGraph& graph = out_.graph;
    if (forward.end == TraceEnd::Closed) {
      curve.points = forward.points;
      curve.start = curve.end = graph.node_at(curve.points.front(), 0.0);
      graph.nodes[static_cast<std::size_t>(curve.start)].position = curve.points.front();
    } else {
      curve.points.assign(backward.points.rbegin(), backward.points.rend());
      curve.points.insert(curve.points.end(), forward.points.begin() + 1, forward.points.end());
      const double merge = 1e-9 * box_.diagonal();
      curve.start = graph.node_at(curve.points.front(), merge);
      curve.end = graph.node_at(curve.points.back(), merge);
      curve.points.front() = graph.nodes[static_cast<std::size_t>(curve.start)].position;
      curve.points.back() = graph.nodes[static_cast<std::size_t>(curve.end)].position;
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
    const Vec3 left = a.value_gradient(m).gradient.normalized().cross(t).normalized();
    const bool first_on_left = face_beside(pair.first, a, m, left);
    curve.left = first_on_left ? pair.first : pair.second;
    curve.right = first_on_left ? pair.second : pair.first;
    return curve;
  }
};

}  // namespace

CreaseSearch find_creases(FaceSet& faces, const Box& box, double cell, std::size_t cover_budget) {
  CreaseSearch out;
  const double longest = (box.hi - box.lo).maxCoeff();
  Settings mc;
  mc.box = box;
  mc.grid = static_cast<int>(std::clamp(std::ceil(longest / cell), 16.0, 128.0));
  out.samples.mesh = marching_cubes(*faces.whole(), mc);
  out.samples.cell = longest / mc.grid;
  for (const Vec3& p : out.samples.mesh.positions) out.samples.face.push_back(faces.face_at(p));
  Search search(faces, box, out, cover_budget);
  search.merge_smooth_pairs();
  if (!search.trace_grid_seeds() || !search.certify()) return out;
  search.report_contacts();
  return out;
}

}  // namespace isopatch
