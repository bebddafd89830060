// The curves where f = 0 meets a face of the tile grid, traced once and read by both tiles beside it
// (tiles.hpp). Marching squares on a regular grid of samples (Lorensen & Cline's cases in two
// dimensions, the saddle decided by f at the cell's centre), crossings by bisection on the sample
// edges, then every curve sampled again by arc length and put on f = 0 within the face's plane.
#include <isopatch/error.hpp>
#include <isopatch/tiles.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace isopatch {
namespace {

constexpr int kMaxSideSamples = 1 << 24;
constexpr double kSamplesPerSpacing = 4.0;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

double checked_value(const Surface& surface, const Vec3& p) {
  const double value = surface.value(p);
  if (!std::isfinite(value))
    throw EvaluationError("f is not finite at (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
                          ", " + std::to_string(p.z()) + ") on a tile face");
  return value;
}

/// The samples along lattice cell `cell` of `axis`: the same count wherever that lattice edge is read.
int side_samples(const TileGrid& grid, int axis, int cell, double spacing) {
  const double length = grid.plane(axis, cell + 1) - grid.plane(axis, cell);
  const double samples = std::ceil(length * kSamplesPerSpacing / spacing);
  if (!(samples <= kMaxSideSamples))
    throw SettingError("spacing", "the face curves' spacing leaves more than 2^24 samples on a tile side");
  return std::max(1, static_cast<int>(samples));
}

/// The crossing of f = 0 between `in` (f < 0) and `out` (f >= 0), points that differ in one coordinate:
/// bisection to the last bit, the last point found inside. Never `out` itself, so a crossing at a
/// sample where f is exactly 0 is not shared by two sample edges.
Vec3 bisect(const Surface& surface, Vec3 in, Vec3 out) {
  for (int i = 0; i < 80; ++i) {
    const Vec3 mid = 0.5 * (in + out);
    if (mid == in || mid == out) break;
    if (checked_value(surface, mid) < 0.0)
      in = mid;
    else
      out = mid;
  }
  return in;
}

/// The face's samples and the crossings on the edges between them.
class FaceSampling {
 public:
  FaceSampling(const Surface& surface, const TileGrid& grid, const TileFace& face, double spacing)
      : surface_(surface), face_(face) {
    u_ = (face.axis + 1) % 3;
    v_ = (face.axis + 2) % 3;
    mu_ = side_samples(grid, u_, face.cell[0], spacing);
    mv_ = side_samples(grid, v_, face.cell[1], spacing);
    coordinate_ = grid.plane(face.axis, face.index);
    us_.resize(static_cast<std::size_t>(mu_) + 1);
    vs_.resize(static_cast<std::size_t>(mv_) + 1);
    for (int i = 0; i <= mu_; ++i) us_[static_cast<std::size_t>(i)] = grid.sample(u_, face.cell[0], i, mu_);
    for (int j = 0; j <= mv_; ++j) vs_[static_cast<std::size_t>(j)] = grid.sample(v_, face.cell[1], j, mv_);
    inside_.resize(us_.size() * vs_.size());
    for (int j = 0; j <= mv_; ++j)
      for (int i = 0; i <= mu_; ++i) inside_[node(i, j)] = checked_value(surface, point(i, j)) < 0.0;
  }

  int mu() const { return mu_; }
  int mv() const { return mv_; }
  bool inside(int i, int j) const { return inside_[node(i, j)] != 0; }
  Vec3 point(double u, double v) const {
    Vec3 p;
    p[face_.axis] = coordinate_;
    p[u_] = u;
    p[v_] = v;
    return p;
  }
  Vec3 point(int i, int j) const {
    return point(us_[static_cast<std::size_t>(i)], vs_[static_cast<std::size_t>(j)]);
  }
  int axis() const { return face_.axis; }
  /// Whether p and q lie on one side of the face (both on the same line of the lattice).
  bool same_side(const Vec3& p, const Vec3& q) const {
    const auto on = [](double x, const std::vector<double>& ends) {
      return x == ends.front() || x == ends.back();
    };
    return (p[u_] == q[u_] && on(p[u_], us_)) || (p[v_] == q[v_] && on(p[v_], vs_));
  }
  /// Whether p lies on the face's rectangle (its in-plane coordinates within the sides).
  bool within(const Vec3& p) const {
    return p[u_] >= us_.front() && p[u_] <= us_.back() && p[v_] >= vs_.front() && p[v_] <= vs_.back();
  }
  double coordinate() const { return coordinate_; }

  /// The crossing on the edge from sample (i, j) one step along u (along_u) or v, numbered on first use.
  std::uint32_t crossing(int i, int j, bool along_u) {
    const std::size_t key = 2 * node(i, j) + (along_u ? 0 : 1);
    const auto found = crossing_of_.find(key);
    if (found != crossing_of_.end()) return found->second;
    const int i2 = along_u ? i + 1 : i, j2 = along_u ? j : j + 1;
    const bool a_in = inside(i, j);
    const Vec3 p = bisect(surface_, a_in ? point(i, j) : point(i2, j2), a_in ? point(i2, j2) : point(i, j));
    const auto id = static_cast<std::uint32_t>(points.size());
    points.push_back(p);
    on_side.push_back((along_u && (j == 0 || j == mv_)) || (!along_u && (i == 0 || i == mu_)));
    crossing_of_.emplace(key, id);
    return id;
  }
  double centre_value(int i, int j) const {
    const double u = 0.5 * (us_[static_cast<std::size_t>(i)] + us_[static_cast<std::size_t>(i) + 1]);
    const double v = 0.5 * (vs_[static_cast<std::size_t>(j)] + vs_[static_cast<std::size_t>(j) + 1]);
    return checked_value(surface_, point(u, v));
  }

  std::vector<Vec3> points;
  std::vector<std::uint8_t> on_side;

 private:
  std::size_t node(int i, int j) const {
    return static_cast<std::size_t>(j) * us_.size() + static_cast<std::size_t>(i);
  }

  const Surface& surface_;
  TileFace face_;
  int u_ = 1, v_ = 2, mu_ = 1, mv_ = 1;
  double coordinate_ = 0.0;
  std::vector<double> us_, vs_;
  std::vector<std::uint8_t> inside_;
  std::map<std::size_t, std::uint32_t> crossing_of_;
};

/// The segments of marching squares, as pairs of crossing numbers, cells in order.
std::vector<std::array<std::uint32_t, 2>> square_segments(FaceSampling& s) {
  std::vector<std::array<std::uint32_t, 2>> segments;
  for (int j = 0; j < s.mv(); ++j)
    for (int i = 0; i < s.mu(); ++i) {
      const bool c00 = s.inside(i, j), c10 = s.inside(i + 1, j), c11 = s.inside(i + 1, j + 1),
                 c01 = s.inside(i, j + 1);
      // The cell's sides in order bottom, right, top, left, and whether each is crossed.
      const bool crossed[4] = {c00 != c10, c10 != c11, c01 != c11, c00 != c01};
      const auto side = [&](int k) {
        switch (k) {
          case 0:
            return s.crossing(i, j, true);
          case 1:
            return s.crossing(i + 1, j, false);
          case 2:
            return s.crossing(i, j + 1, true);
          default:
            return s.crossing(i, j, false);
        }
      };
      const int count = crossed[0] + crossed[1] + crossed[2] + crossed[3];
      if (count == 2) {
        int first = -1, second = -1;
        for (int k = 0; k < 4; ++k)
          if (crossed[k]) (first < 0 ? first : second) = k;
        segments.push_back({side(first), side(second)});
      } else if (count == 4) {
        // A saddle: the corners of the centre's sign are joined through it.
        if ((s.centre_value(i, j) < 0.0) == c00) {
          segments.push_back({side(0), side(1)});  // cuts off the corner (i + 1, j)
          segments.push_back({side(2), side(3)});  // and (i, j + 1)
        } else {
          segments.push_back({side(3), side(0)});  // cuts off (i, j)
          segments.push_back({side(1), side(2)});  // and (i + 1, j + 1)
        }
      }
    }
  return segments;
}

/// The segments linked into curves: open ones from a side crossing (ascending numbers first), then
/// closed ones (repeating their first number).
std::vector<std::vector<std::uint32_t>> link_segments(
    const FaceSampling& s, const std::vector<std::array<std::uint32_t, 2>>& segments) {
  const std::size_t n = s.points.size();
  std::vector<std::array<std::uint32_t, 2>> next(n, {kNone, kNone});
  for (const auto& seg : segments)
    for (int e = 0; e < 2; ++e) {
      auto& slots = next[seg[static_cast<std::size_t>(e)]];
      (slots[0] == kNone ? slots[0] : slots[1]) = seg[static_cast<std::size_t>(1 - e)];
    }
  std::vector<std::uint8_t> used(n, 0);
  std::vector<std::vector<std::uint32_t>> curves;
  const auto walk = [&](std::uint32_t start) {
    std::vector<std::uint32_t> curve{start};
    used[start] = 1;
    std::uint32_t previous = kNone, current = start;
    for (;;) {
      const auto& slots = next[current];
      const std::uint32_t to = slots[0] != previous && slots[0] != kNone ? slots[0] : slots[1];
      if (to == kNone || to == previous) break;
      curve.push_back(to);
      if (to == start) break;
      if (used[to]) break;
      used[to] = 1;
      previous = current;
      current = to;
    }
    curves.push_back(std::move(curve));
  };
  for (std::uint32_t p = 0; p < n; ++p)
    if (!used[p] && s.on_side[p]) walk(p);
  for (std::uint32_t p = 0; p < n; ++p)
    if (!used[p]) walk(p);
  return curves;
}

/// p put on f = 0 within the face's plane (Newton along the in-plane gradient); false when it does not
/// converge within the face's rectangle grown by `reach`.
bool onto_curve(const Surface& surface, const FaceSampling& s, Vec3& p, double tolerance, double reach,
                const Vec3& start) {
  for (int it = 0; it < 30; ++it) {
    const ValueGradient vg = surface.value_gradient(p);
    Vec3 g = vg.gradient;
    g[s.axis()] = 0.0;
    const double g2 = g.squaredNorm();
    if (!std::isfinite(vg.value) || !std::isfinite(g2) || g2 == 0.0) return false;
    const Vec3 step = (vg.value / g2) * g;
    p -= step;
    p[s.axis()] = s.coordinate();
    if ((p - start).norm() > reach || !s.within(p)) return false;
    if (step.norm() <= tolerance) return true;
  }
  return false;
}

}  // namespace

FaceCurves face_curves(const Surface& surface, const TileGrid& grid, const TileFace& face, double spacing) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw SettingError("spacing", "the face curves' spacing must be positive and finite");
  FaceSampling s(surface, grid, face, spacing);
  const auto segments = square_segments(s);
  const auto traced = link_segments(s, segments);

  FaceCurves out;
  out.face = face;
  out.spacing = spacing;
  const double tolerance = 1e-13 * std::max(grid.domain.diagonal(), 1e-300);
  for (const auto& curve : traced) {
    if (curve.size() < 2) continue;
    const bool closed = curve.front() == curve.back();
    std::vector<double> arc{0.0};
    for (std::size_t i = 1; i < curve.size(); ++i)
      arc.push_back(arc.back() + (s.points[curve[i]] - s.points[curve[i - 1]]).norm());
    const double length = arc.back();
    if (!(length > 0.0)) continue;
    int pieces = static_cast<int>(std::lround(length / spacing));
    // A closed curve is at least a triangle; an open one whose ends are on one side of the face bounds,
    // with the curve across that side on the next face, a lens: two pieces each make it a quadrilateral.
    const bool lens = !closed && s.same_side(s.points[curve.front()], s.points[curve.back()]);
    pieces = std::max(pieces, closed ? 3 : lens ? 2 : 1);
    std::vector<std::uint32_t> numbers;
    const auto add = [&](const Vec3& p) {
      numbers.push_back(static_cast<std::uint32_t>(out.points.size()));
      out.points.push_back(p);
    };
    add(s.points[curve.front()]);
    std::size_t segment = 1;
    for (int k = 1; k < pieces; ++k) {
      const double at = length * (static_cast<double>(k) / pieces);
      while (segment + 1 < arc.size() && arc[segment] < at) ++segment;
      const double w = (at - arc[segment - 1]) / std::max(arc[segment] - arc[segment - 1], 1e-300);
      const Vec3 start = (1.0 - w) * s.points[curve[segment - 1]] + w * s.points[curve[segment]];
      Vec3 p = start;
      p[s.axis()] = s.coordinate();
      // Off the curve after Newton (it did not converge): the nearer traced point, which is on it.
      if (!onto_curve(surface, s, p, tolerance, 0.5 * spacing, start))
        p = s.points[curve[w < 0.5 ? segment - 1 : segment]];
      add(p);
    }
    if (closed)
      numbers.push_back(numbers.front());
    else
      add(s.points[curve.back()]);
    out.curves.push_back(std::move(numbers));
  }
  return out;
}

}  // namespace isopatch
