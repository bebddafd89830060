// Narrow corners at a held boundary (cap_wedges.hpp).
#include "api/cap_wedges.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <set>

#include "core/triangle_angle.hpp"
#include "surface/project_point.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

namespace {

/// Relaxation rounds and the share of the way to the centroid tried in each.
constexpr int kRelaxRounds = 8;
/// Rounds of flips and relaxation at one narrow corner.
constexpr int kFlipAttempts = 4;
constexpr std::array<double, 3> kRelaxSteps{1.0, 0.5, 0.25};

double angle_at(const Vec3& at, const Vec3& a, const Vec3& b) {
  const Vec3 u = a - at, v = b - at;
  return std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / std::numbers::pi;
}

class Corners {
 public:
  /// Only the held vertices and their neighbours get their triangles listed (every flip and move stays
  /// among them): a cut of millions of vertices holds a few percent of them.
  Corners(Mesh& cap, const Surface& surface, const std::vector<bool>& held, double tolerance)
      : cap_(cap), f_(surface), held_(held), tolerance_(tolerance), slot_(cap.positions.size(), kNoSlot) {
    for (const Triangle& t : cap.triangles)
      if (held[t[0]] || held[t[1]] || held[t[2]])
        for (std::uint32_t v : t)
          if (slot_[v] == kNoSlot) slot_[v] = static_cast<std::uint32_t>(sets_.size()), sets_.emplace_back();
    for (std::size_t t = 0; t < cap.triangles.size(); ++t)
      for (std::uint32_t v : cap.triangles[t])
        if (slot_[v] != kNoSlot) sets_[slot_[v]].insert(t);
  }

  void open(double narrow) {
    std::set<std::uint32_t> freed;
    for (std::uint32_t v = 0; v < cap_.positions.size(); ++v) {
      if (!held_[v] || slot_[v] == kNoSlot || around(v).size() < 2) continue;
      const double angle = span(v);
      if (angle >= narrow) continue;
      // The triangles the corner's angle holds at about 60 degrees each.
      const std::size_t want = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(angle / 60.0)));
      // Flip the inner edges at v while one's quadrilateral is convex; where none is, relax the free
      // vertices at v first (a vertex just inside the line of v's neighbours makes its quadrilateral
      // concave).
      for (int attempt = 0; attempt < kFlipAttempts && around(v).size() > want; ++attempt) {
        for (bool flipped = true; flipped && around(v).size() > want;) {
          flipped = false;
          for (std::size_t t : std::set<std::size_t>(around(v)))
            if (flip_next_edge(v, t, freed)) {
              flipped = true;
              break;
            }
        }
        for (std::uint32_t w : ring_of(v)) relax(w);
      }
    }
    for (int round = 0; round < kRelaxRounds; ++round)
      for (std::uint32_t w : freed) relax(w);
  }

 private:
  Mesh& cap_;
  Sampler f_;
  const std::vector<bool>& held_;
  double tolerance_;
  static constexpr std::uint32_t kNoSlot = 0xffffffffu;
  std::vector<std::uint32_t> slot_;          ///< per vertex, its entry in sets_ (kNoSlot: none)
  std::vector<std::set<std::size_t>> sets_;  ///< the triangles at a held vertex or a neighbour of one

  /// The triangles at v. \pre v is held or a neighbour of a held vertex (where every use lies).
  std::set<std::size_t>& around(std::uint32_t v) { return sets_[slot_[v]]; }
  const std::set<std::size_t>& around(std::uint32_t v) const { return sets_[slot_[v]]; }

  const Vec3& at(std::uint32_t v) const { return cap_.positions[v]; }
  /// Twice the triangle's area about grad f at its centroid: > 0 when it faces along the surface.
  double area(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    const Vec3 normal = f_.value_gradient((at(a) + at(b) + at(c)) / 3.0).gradient.normalized();
    return (at(b) - at(a)).cross(at(c) - at(a)).dot(normal);
  }

  /// The angle the cap spans at v (its triangles' angles there, summed).
  double span(std::uint32_t v) const {
    double sum = 0.0;
    for (std::size_t t : around(v)) {
      const Triangle& tri = cap_.triangles[t];
      const int k = tri[0] == v ? 0 : (tri[1] == v ? 1 : 2);
      sum += angle_at(at(v), at(tri[(k + 1) % 3]), at(tri[(k + 2) % 3]));
    }
    return sum;
  }

  /// Flips the edge from v to the next corner of triangle t (v, a, w), shared with (v, w, b), into a - b
  /// when the quadrilateral v a w b is convex and w is free.
  bool flip_next_edge(std::uint32_t v, std::size_t t, std::set<std::uint32_t>& freed) {
    const Triangle tri = cap_.triangles[t];
    const int k = tri[0] == v ? 0 : (tri[1] == v ? 1 : 2);
    const std::uint32_t a = tri[(k + 1) % 3], w = tri[(k + 2) % 3];
    if (held_[w]) return false;
    for (std::size_t u : around(v)) {
      if (u == t || !around(w).count(u)) continue;
      const Triangle other = cap_.triangles[u];
      const int j = other[0] == v ? 0 : (other[1] == v ? 1 : 2);
      if (other[(j + 1) % 3] != w) continue;
      const std::uint32_t b = other[(j + 2) % 3];
      if (!(area(v, a, b) > 0.0)) return false;
      if (!(area(a, w, b) > 0.0) && !move_beyond(w, v, a, b)) return false;
      for (std::size_t s : around(a))
        if (around(b).count(s)) return false;  // a - b is an edge already
      cap_.triangles[t] = {v, a, b};
      cap_.triangles[u] = {a, w, b};
      around(w).erase(t);
      around(v).erase(u);
      around(b).insert(t);
      around(a).insert(u);
      freed.insert(w);
      return true;
    }
    return false;
  }

  /// Moves w beyond the line a - b, away from v, where all of w's triangles stay upright (so that the
  /// quadrilateral v a w b becomes convex); false when no trial position keeps them upright.
  bool move_beyond(std::uint32_t w, std::uint32_t v, std::uint32_t a, std::uint32_t b) {
    const Vec3 start = at(w), middle = 0.5 * (at(a) + at(b));
    for (const double share : {0.3, 0.6}) {
      cap_.positions[w] = middle + share * (middle - at(v));
      if (!settle(w, start)) continue;
      bool upright = area(a, w, b) > 0.0;
      for (std::size_t t : around(w)) {
        const Triangle& tri = cap_.triangles[t];
        upright = upright && area(tri[0], tri[1], tri[2]) > 0.0;
      }
      if (upright) return true;
    }
    cap_.positions[w] = start;
    return false;
  }

  /// Puts w back on f = 0 (Newton steps no longer than its move from `from`).
  bool settle(std::uint32_t w, const Vec3& from) {
    const double step = (cap_.positions[w] - from).norm() + tolerance_;
    return project_to_surface(f_, cap_.positions[w], tolerance_, step);
  }

  double smallest_angle_around(std::uint32_t w) const {
    double smallest = 180.0;
    for (std::size_t t : around(w)) {
      const Triangle& tri = cap_.triangles[t];
      smallest = std::min(smallest, smallest_angle(at(tri[0]), at(tri[1]), at(tri[2])));
    }
    return smallest;
  }

  std::set<std::uint32_t> ring_of(std::uint32_t w) const {
    std::set<std::uint32_t> ring;
    for (std::size_t t : around(w))
      for (std::uint32_t u : cap_.triangles[t])
        if (u != w) ring.insert(u);
    return ring;
  }

  void relax(std::uint32_t w) {
    if (held_[w]) return;
    const std::set<std::uint32_t> ring = ring_of(w);
    if (ring.empty()) return;
    Vec3 centroid = Vec3::Zero();
    for (std::uint32_t u : ring) centroid += at(u);
    centroid /= static_cast<double>(ring.size());
    const Vec3 start = at(w);
    const double before = smallest_angle_around(w);
    for (const double step : kRelaxSteps) {
      cap_.positions[w] = start + step * (centroid - start);
      if (!settle(w, start)) continue;
      bool upright = true;
      for (std::size_t t : around(w)) {
        const Triangle& tri = cap_.triangles[t];
        upright = upright && area(tri[0], tri[1], tri[2]) > 0.0;
      }
      if (upright && smallest_angle_around(w) > before) return;
    }
    cap_.positions[w] = start;
  }
};

}  // namespace

void open_narrow_corners(Mesh& mesh, const Surface& surface, const std::vector<bool>& held,
                         double narrow_degrees, double tolerance) {
  Corners(mesh, surface, held, tolerance).open(narrow_degrees);
}

}  // namespace isopatch
