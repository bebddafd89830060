/// \file face_regions.cpp
/// Faces cut into disc-like pieces by planes (face_regions.hpp).
#include "csg/face_regions.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <utility>

#include "core/point_grid.hpp"
#include "csg/face_cut.hpp"
#include "csg/face_parts.hpp"

namespace isopatch {

namespace {

/// A part whose normals stray from their mean by more than this (radians) is cut.
constexpr double kMaxNormalStray = std::numbers::pi / 3.0;
/// At most this many cuts in all.
constexpr int kMaxCuts = 512;
/// Points of each side that vote for the part its cycle bounds.
constexpr std::size_t kVotesPerSide = 8;
/// A piece whose boundary turns right by more than this (radians) in one stretch is cut.
constexpr double kMaxConcaveTurn = 0.6 * std::numbers::pi;
/// A piece with a reflex corner turning right by more than this (radians) is cut through it.
constexpr double kMaxReflexTurn = std::numbers::pi / 3.0;

/// Points by grid cell, for nearest-point queries within at most `cell`.
class VertexGrid {
 public:
  VertexGrid(const std::vector<Vec3>& points, double cell) : points_(points), grid_(cell) {
    for (std::size_t v = 0; v < points.size(); ++v) grid_.insert(points[v], v);
  }
  /// The nearest point within `reach` (<= cell) of p that `accept` takes (the lowest id among equals),
  /// or -1.
  template <class Accept>
  int nearest(const Vec3& p, double reach, Accept accept) const {
    int best = -1;
    double best_d = reach;
    grid_.near(p, [&](std::size_t id) {
      const auto v = static_cast<int>(id);
      const double d = (points_[id] - p).norm();
      if (d <= best_d && accept(v) && (best < 0 || d < best_d || v < best)) {
        best_d = d;
        best = v;
      }
    });
    return best;
  }

 private:
  const std::vector<Vec3>& points_;
  PointGrid grid_;
};

}  // namespace

std::vector<FaceCycle> cut_into_discs(CreaseGraph& graph, FaceSet& faces, const ShapeSamples& samples,
                                      const Box& box) {
  Parts parts = initial_parts(samples);
  const double h = samples.cell;
  PlaneCutter cutter{graph, faces, samples, parts, h, 1e-13 * box.diagonal(), box, {}};
  const VertexGrid grid(samples.mesh.positions, 2.0 * h);
  std::vector<Vec3> normals;
  for (std::size_t v = 0; v < samples.mesh.positions.size(); ++v)
    normals.push_back(
        faces.function(samples.face[v])->value_gradient(samples.mesh.positions[v]).gradient.normalized());
  for (int cuts = 0; cuts <= kMaxCuts; ++cuts) {
    std::vector<FaceCycle> cycles = face_cycles(graph, faces);
    // Each cycle's part: the vote of the coarse vertices of its face nearest to its crease points.
    std::map<int, std::vector<const FaceCycle*>> cycles_of;
    for (const FaceCycle& c : cycles) {
      std::map<int, int> votes;
      bool any_crease = false;
      for (const HalfCurve& s : c.sides) any_crease |= !graph.curves[static_cast<std::size_t>(s.curve)].seam;
      const Surface& fc = *faces.function(c.face);
      for (const HalfCurve& s : c.sides) {
        const GraphCurve& curve = graph.curves[static_cast<std::size_t>(s.curve)];
        if (any_crease && curve.seam) continue;
        // Each point votes from a little inside the piece (to the left of the cycle), so that the two
        // sides of a seam vote for their own parts.
        const std::vector<Vec3> p = half_points(graph, s);
        const std::size_t stride = std::max<std::size_t>(1, (p.size() - 1) / kVotesPerSide);
        for (std::size_t k = stride / 2; k + 1 < p.size(); k += stride) {
          const Vec3 m = 0.5 * (p[k] + p[k + 1]);
          const Vec3 left = fc.value_gradient(m).gradient.cross(p[k + 1] - p[k]).normalized();
          const int v = grid.nearest(m + 0.75 * h * left, 1.5 * h, [&](int w) {
            return samples.face[static_cast<std::size_t>(w)] == c.face;
          });
          if (v >= 0) ++votes[parts.part[static_cast<std::size_t>(v)]];
        }
      }
      int best = -1, most = 0;
      for (const auto& [part, n] : votes)
        if (n > most) {
          most = n;
          best = part;
        }
      if (best >= 0) cycles_of[best].push_back(&c);
    }
    // The first part that needs a cut, and the plane.
    std::vector<std::vector<int>> members(static_cast<std::size_t>(parts.count));
    for (std::size_t v = 0; v < parts.part.size(); ++v)
      members[static_cast<std::size_t>(parts.part[v])].push_back(static_cast<int>(v));
    // The curves' points with their faces, built when a part without cycles needs them.
    std::optional<std::pair<std::vector<Vec3>, std::vector<std::pair<int, int>>>> curve_points;
    std::optional<VertexGrid> curve_grid;
    // Every part that needs a cut and whose cycles no cut of this round has changed is cut this round.
    const int part_count = parts.count;
    std::set<int> cut_faces;
    cutter.touched.clear();
    for (int part = 0; part < part_count; ++part) {
      const std::vector<int>& m = members[static_cast<std::size_t>(part)];
      if (m.size() < 3) continue;
      const int g = samples.face[static_cast<std::size_t>(m.front())];
      const std::vector<const FaceCycle*>& mine = cycles_of[part];
      if (cut_faces.count(g)) continue;
      if (std::any_of(mine.begin(), mine.end(), [&](const FaceCycle* c) {
            return std::any_of(c->sides.begin(), c->sides.end(),
                               [&](const HalfCurve& s) { return cutter.touched.count(s.curve) > 0; });
          }))
        continue;
      Vec3 centroid = Vec3::Zero(), lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300),
           mean = Vec3::Zero();
      for (const int v : m) {
        const Vec3& p = samples.mesh.positions[static_cast<std::size_t>(v)];
        centroid += p;
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
        mean += normals[static_cast<std::size_t>(v)];
      }
      centroid /= static_cast<double>(m.size());
      std::vector<Plane> planes;
      if (mine.size() >= 2) {
        // Through the shortest cycle (a hole), across it: the axis most across its normal and longest.
        const FaceCycle* shortest = mine.front();
        CycleShape best = cycle_shape(graph, *shortest);
        for (const FaceCycle* c : mine) {
          CycleShape s = cycle_shape(graph, *c);
          if (s.length < best.length) best = std::move(s);
        }
        std::array<int, 3> axes{0, 1, 2};
        std::sort(axes.begin(), axes.end(), [&](int a, int b) {
          const double da = std::abs(best.normal[a]) - 0.1 * (hi - lo)[a] / (hi - lo).norm();
          const double db = std::abs(best.normal[b]) - 0.1 * (hi - lo)[b] / (hi - lo).norm();
          return da < db || (da == db && a < b);
        });
        for (const int a : axes) planes.push_back({Vec3::Unit(a), best.centroid[a]});
      } else {
        double stray = 0.0;
        const Vec3 n = mean.normalized();
        Vec3 spread = Vec3::Zero();
        for (const int v : m) {
          const Vec3& nv = normals[static_cast<std::size_t>(v)];
          stray = std::max(stray, std::acos(std::clamp(nv.dot(n), -1.0, 1.0)));
          spread += (nv - n).cwiseAbs2();
        }
        const bool closed = mine.empty();
        if (closed) {
          // A face with no crease here: only a real part of one (not a sliver along a crease of it).
          if (!curve_points) {
            curve_points.emplace();
            for (const GraphCurve& c : graph.curves)
              for (std::size_t k = 0; k < c.points.size(); k += 2) {
                curve_points->first.push_back(c.points[k]);
                curve_points->second.push_back({c.left, c.right});
              }
            curve_grid.emplace(curve_points->first, 2.0 * h);
          }
          bool near_curve = false;
          const std::size_t stride = std::max<std::size_t>(1, m.size() / 32);
          for (std::size_t k = 0; k < m.size() && !near_curve; k += stride)
            near_curve = curve_grid->nearest(
                             samples.mesh.positions[static_cast<std::size_t>(m[k])], 2.0 * h, [&](int w) {
                               const auto [l, r] = curve_points->second[static_cast<std::size_t>(w)];
                               return l == g || r == g;
                             }) >= 0;
          if (near_curve) continue;
        }
        if (!closed && stray <= kMaxNormalStray && mine.front()->sides.size() <= 12) {
          // A piece whose boundary turns right by much in one stretch (a notch, half a hole) is cut
          // across the notch's middle.
          const Concavity notch = concavity(cycle_shape(graph, *mine.front()), *faces.function(g));
          const bool reflex = notch.sharpest > kMaxReflexTurn;
          if (!reflex && notch.turn <= kMaxConcaveTurn) continue;
          // Through a reflex corner along the side that arrives at it, else across the notch's middle.
          const Vec3 along = reflex ? notch.sharpest_in : notch.chord;
          const Vec3 at = reflex ? notch.sharpest_at : notch.middle;
          std::array<int, 3> axes{0, 1, 2};
          std::sort(axes.begin(), axes.end(), [&](int a, int b) {
            return std::abs(along[a]) > std::abs(along[b]) ||
                   (std::abs(along[a]) == std::abs(along[b]) && a < b);
          });
          for (const int a : axes) planes.push_back({Vec3::Unit(a), at[a]});
        }
        if (planes.empty()) {
          // Across the direction the normals (or, for a flat part with too many sides, the points) vary most.
          const Vec3 key = stray > kMaxNormalStray ? spread : Vec3(hi - lo);
          std::array<int, 3> axes{0, 1, 2};
          std::sort(axes.begin(), axes.end(),
                    [&](int a, int b) { return key[a] > key[b] || (key[a] == key[b] && a < b); });
          for (const int a : axes) planes.push_back({Vec3::Unit(a), centroid[a]});
        }
      }
      for (const Plane& candidate : planes) {
        // Offsets on a lattice of half cells from the box's centre: the parts of neighbouring faces cut
        // near the same place are cut by the same plane, so their seams meet the shared creases at the
        // same points (and symmetric shapes are cut on their planes of symmetry).
        Plane lattice = candidate;
        const int axis = candidate.normal.x() != 0.0 ? 0 : (candidate.normal.y() != 0.0 ? 1 : 2);
        const double centre = 0.5 * (box.lo[axis] + box.hi[axis]);
        lattice.offset = centre + std::round((candidate.offset - centre) / (0.5 * h)) * (0.5 * h);
        if (cutter.cut(g, part, mine, cutter.snapped_to_nodes(lattice, mine)) > 0) {
          cut_faces.insert(g);
          break;
        }
      }
      if (!cut_faces.count(g))
        throw CreaseError("a face of the shape near " + point_text(centroid) +
                          " could not be cut into disc-like pieces");
    }
    if (cut_faces.empty()) return cycles;
  }
  throw CreaseError("cutting the faces of the shape into disc-like pieces did not end");
}

}  // namespace isopatch
