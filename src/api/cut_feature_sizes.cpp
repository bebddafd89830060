// Sizes at small features of the cut (see cut_feature_sizes.hpp, docs/algorithms.md 4.11).
#include "api/cut_feature_sizes.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

#include "remesh/box_boundary.hpp"

#include <tbb/parallel_for.h>

namespace isopatch {

namespace {

/// A plane that cuts the surface: a box face or a region plane, with an in-plane frame.
struct CuttingFace {
  Vec3 normal = Vec3::UnitX();  ///< unit
  Vec3 origin = Vec3::Zero();   ///< a point on it, the middle of its sampled square
  Vec3 u = Vec3::UnitY(), v = Vec3::UnitZ();
  double half_u = 0.0, half_v = 0.0;
  int box_axis = -1;      ///< the box face's axis, or -1 for a region plane
  int region_plane = -1;  ///< the region plane's index, or -1 for a box face
};

/// Everything a point of a face must satisfy: inside the box and the region's planes.
struct Domain {
  Box box;
  std::vector<CutPlane> planes;  ///< the region's, with unit normals (box_boundary.hpp)
  double tolerance = 0.0;

  bool contains(const Vec3& p, const CuttingFace& face) const {
    if (!box.contains(p, tolerance)) return false;
    for (std::size_t j = 0; j < planes.size(); ++j)
      if (static_cast<int>(j) != face.region_plane && planes[j].distance(p) > tolerance) return false;
    return true;
  }

  /// The point (a, b) of the face's frame, clamped into the box (f is never evaluated outside it) and,
  /// on a box face, exactly on it.
  Vec3 on_face(const CuttingFace& face, double a, double b) const {
    Vec3 p = (face.origin + a * face.u + b * face.v).cwiseMax(box.lo).cwiseMin(box.hi);
    if (face.box_axis >= 0) p[face.box_axis] = face.origin[face.box_axis];
    return p;
  }

  /// The unit normal of the constraint p violates most (a box face or a plane), or nullopt inside.
  std::optional<Vec3> violated(const Vec3& p, const CuttingFace& face) const {
    double worst = tolerance;
    std::optional<Vec3> n;
    for (int a = 0; a < 3; ++a) {
      if (box.lo[a] - p[a] > worst) worst = box.lo[a] - p[a], n = -Vec3::Unit(a);
      if (p[a] - box.hi[a] > worst) worst = p[a] - box.hi[a], n = Vec3::Unit(a);
    }
    for (std::size_t j = 0; j < planes.size(); ++j) {
      const double d = planes[j].distance(p);
      if (static_cast<int>(j) != face.region_plane && d > worst) worst = d, n = planes[j].normal;
    }
    return n;
  }
};

std::vector<CuttingFace> cutting_faces(const Box& box, const Domain& domain) {
  std::vector<CuttingFace> faces;
  const Vec3 centre = box.centre(), half = 0.5 * box.size();
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      CuttingFace f;
      f.box_axis = a;
      f.normal = (side ? 1.0 : -1.0) * Vec3::Unit(a);
      f.origin = centre;
      f.origin[a] = side ? box.hi[a] : box.lo[a];
      f.u = Vec3::Unit((a + 1) % 3);
      f.v = Vec3::Unit((a + 2) % 3);
      f.half_u = half[(a + 1) % 3];
      f.half_v = half[(a + 2) % 3];
      faces.push_back(f);
    }
  const double radius = half.norm();
  for (std::size_t j = 0; j < domain.planes.size(); ++j) {
    CuttingFace f;
    f.region_plane = static_cast<int>(j);
    f.normal = domain.planes[j].normal;
    f.origin = centre - domain.planes[j].distance(centre) * f.normal;
    const Vec3 helper = std::abs(f.normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    f.u = f.normal.cross(helper).normalized();
    f.v = f.normal.cross(f.u);
    f.half_u = f.half_v = radius;
    faces.push_back(f);
  }
  return faces;
}

/// f at every point, in one batch.
std::vector<double> values_at(const Surface& surface, const std::vector<Vec3>& points) {
  std::vector<double> out(points.size());
  if (!points.empty()) surface.values(points, out);
  return out;
}

/// One point of a cut curve: where it is, the unit in-plane direction across the curve (towards f > 0).
struct CurvePoint {
  Vec3 point;
  Vec3 across;
  double curvature = 0.0;
};

/// The points where f changes sign along the lines of a grid of spacing edge/4 on the face (at most
/// max_samples per side), by linear interpolation, in the box. Blocks of grid cells whose interval
/// enclosure of f excludes 0 are not sampled: a closed surface far from its box costs a few enclosures
/// per face.
std::vector<CurvePoint> cut_curve_points(const Surface& surface, const CuttingFace& face,
                                         const Domain& domain, double edge, const CutFeatureParams& params) {
  const double spacing = std::max(edge / 4.0, 2.0 * std::max(face.half_u, face.half_v) / params.max_samples);
  const int nu = std::max(2, static_cast<int>(std::ceil(2.0 * face.half_u / spacing)) + 1);
  const int nv = std::max(2, static_cast<int>(std::ceil(2.0 * face.half_v / spacing)) + 1);
  const double du = 2.0 * face.half_u / (nu - 1), dv = 2.0 * face.half_v / (nv - 1);
  auto at = [&](int i, int j) { return domain.on_face(face, -face.half_u + i * du, -face.half_v + j * dv); };
  const auto index = [nu](int i, int j) {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(nu) + static_cast<std::size_t>(i);
  };
  // Grid points are made when needed, not stored: a face far from the surface costs its enclosures.
  // Per point (`sample` below) 0: not sampled; otherwise the sign that a block's enclosure proves (+1,
  // -1) or 2: sample it. A point on the border of two blocks is sampled when either block is.
  // Blocks of grid cells, from 16 x 16 down to one cell, halved while their enclosure admits 0; their
  // verdicts are recorded first, then marked on the grid.
  struct Verdict {
    int i0, j0, i1, j1;
    signed char sign;  // +1, -1: proved; 2: sample it
  };
  std::vector<Verdict> verdicts;
  const auto record = [&](int i0, int j0, int i1, int j1, signed char verdict) {
    verdicts.push_back({i0, j0, i1, j1, verdict});
  };
  const auto classify = [&](auto&& self, int i0, int j0, int i1, int j1) -> void {
    Box b{at(i0, j0).cwiseMin(at(i1, j1)), at(i0, j0).cwiseMax(at(i1, j1))};
    for (const Vec3& corner : {at(i1, j0), at(i0, j1)}) b = {b.lo.cwiseMin(corner), b.hi.cwiseMax(corner)};
    const std::optional<Interval> f = surface.bound(b);
    if (f && f->excludes_zero()) return record(i0, j0, i1, j1, f->lo > 0.0 ? 1 : -1);
    if (i1 - i0 <= 1 && j1 - j0 <= 1) return record(i0, j0, i1, j1, 2);
    const int im = i1 - i0 > 1 ? (i0 + i1) / 2 : i1, jm = j1 - j0 > 1 ? (j0 + j1) / 2 : j1;
    self(self, i0, j0, im, jm);
    if (im < i1) self(self, im, j0, i1, jm);
    if (jm < j1) self(self, i0, jm, im, j1);
    if (im < i1 && jm < j1) self(self, im, jm, i1, j1);
  };
  const int block = 16;
  for (int j0 = 0; j0 < nv - 1; j0 += block)
    for (int i0 = 0; i0 < nu - 1; i0 += block)
      classify(classify, i0, j0, std::min(i0 + block, nu - 1), std::min(j0 + block, nv - 1));
  // f of one sign proved over the whole face (a closed surface inside its box): no point is sampled and
  // no crossing found, so the grid is not made (its marking and scans were most of a small mesh's search).
  if (std::all_of(verdicts.begin(), verdicts.end(),
                  [&](const Verdict& v) { return v.sign != 2 && v.sign == verdicts.front().sign; }))
    return {};
  std::vector<signed char> sample(static_cast<std::size_t>(nu) * static_cast<std::size_t>(nv), 0);
  for (const Verdict& v : verdicts)
    for (int j = v.j0; j <= v.j1; ++j)
      for (int i = v.i0; i <= v.i1; ++i) {
        signed char& s = sample[index(i, j)];
        s = (v.sign == 2 || s == 2 || (s != 0 && s != v.sign)) ? 2 : v.sign;
      }
  // f at the points to sample inside the domain (NaN outside), in one batch.
  std::vector<std::size_t> kept_index;
  std::vector<Vec3> kept;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      if (sample[index(i, j)] == 2) {
        const Vec3 p = at(i, j);
        if (!domain.contains(p, face)) continue;
        kept_index.push_back(index(i, j));
        kept.push_back(p);
      }
  const std::vector<double> kept_values = values_at(surface, kept);
  const auto sampled = [&](std::size_t k) {
    const auto it = std::lower_bound(kept_index.begin(), kept_index.end(), k);
    return it != kept_index.end() && *it == k ? kept_values[static_cast<std::size_t>(it - kept_index.begin())]
                                              : std::numeric_limits<double>::quiet_NaN();
  };
  // A point's value: sampled, or the sign its block proves; NaN outside the domain.
  const auto value = [&](int i, int j) {
    const std::size_t k = index(i, j);
    if (sample[k] == 2) return sampled(k);
    return domain.contains(at(i, j), face) ? static_cast<double>(sample[k])
                                           : std::numeric_limits<double>::quiet_NaN();
  };
  // Crossings along the grid lines, by linear interpolation. Two points of proved signs never differ
  // (a point between blocks of opposite signs is sampled), so only pairs with a sampled point can cross.
  std::vector<CurvePoint> curve;
  auto crossing = [&](int ia, int ja, int ib, int jb) {
    if (sample[index(ia, ja)] != 2 && sample[index(ib, jb)] != 2) return;
    const double fa = value(ia, ja), fb = value(ib, jb);
    if (!(std::isfinite(fa) && std::isfinite(fb)) || (fa < 0.0) == (fb < 0.0)) return;
    const double t = fa / (fa - fb);
    const Vec3 a = at(ia, ja), b = at(ib, jb);
    const Vec3 p = (a + t * (b - a)).cwiseMax(domain.box.lo).cwiseMin(domain.box.hi);
    curve.push_back({p, Vec3::Zero(), 0.0});
  };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      if (i + 1 < nu) crossing(i, j, i + 1, j);
      if (j + 1 < nv) crossing(i, j, i, j + 1);
    }
  return curve;
}

/// Whether the cut curve reaches the face's border near `exit`, a point just beyond the border whose
/// outward normal is `border_normal`: f changes sign (or vanishes, a curve ending in a box corner) along
/// the border within `reach` of it.
bool curve_ends_near(const Surface& surface, const CuttingFace& face, const Domain& domain, const Vec3& exit,
                     const Vec3& border_normal, double reach) {
  Vec3 w = face.normal.cross(border_normal);
  if (!(w.norm() > 1e-9)) return true;
  w.normalize();
  const Vec3 e = exit.cwiseMax(domain.box.lo).cwiseMin(domain.box.hi);
  const double f0 = surface.value(e);
  const int n = 8;
  for (int s = 1; s <= n; ++s)
    for (double sign : {1.0, -1.0}) {
      const Vec3 q = (e + sign * reach * s / n * w).cwiseMax(domain.box.lo).cwiseMin(domain.box.hi);
      const ValueGradient vg = surface.value_gradient(q);
      if (std::isfinite(vg.value) &&
          ((vg.value < 0.0) != (f0 < 0.0) || std::abs(vg.value) <= 1e-6 * reach * vg.gradient.norm()))
        return true;
    }
  return false;
}

/// The sources of one face: at every point of its cut curves, min(turn / curvature, width), kept when
/// under `relevant` edges.
void face_sources(const Surface& surface, const CuttingFace& face, const Domain& domain, double edge,
                  double smallest, const CutFeatureParams& params, std::vector<SizeSource>& sources) {
  std::vector<CurvePoint> curve = cut_curve_points(surface, face, domain, edge, params);
  if (curve.empty()) return;
  // Curvature of the curve within the plane and the direction across it, from the exact derivatives.
  std::vector<char> usable(curve.size(), 0);
  for (std::size_t c = 0; c < curve.size(); ++c) {
    const SecondOrder so = surface.second_order(curve[c].point);
    // Where f or its derivatives are not finite no size is asked for: the mesher reports it.
    if (!std::isfinite(so.value) || !so.gradient.allFinite() || !so.hessian.allFinite()) continue;
    const Vec3 in_plane = so.gradient - so.gradient.dot(face.normal) * face.normal;
    const double g = in_plane.norm();
    if (!(g > 0.0)) {
      // Tangent to the plane there: the cut has a singular point, the finest size.
      sources.push_back({curve[c].point, smallest});
      continue;
    }
    curve[c].across = in_plane / g;
    const Vec3 along = face.normal.cross(curve[c].across);
    curve[c].curvature = std::abs(along.dot(so.hessian * along)) / g;
    usable[c] = 1;
  }
  // Widths: march across the curve on both sides, up to one edge, in one batch of points.
  const int steps = 8;
  const double step = edge / steps;
  std::vector<Vec3> march;
  std::vector<char> march_inside;
  for (std::size_t c = 0; c < curve.size(); ++c)
    for (int side = 0; side < 2; ++side)
      for (int s = 1; s <= steps; ++s) {
        Vec3 p = curve[c].point + (side ? -1.0 : 1.0) * s * step * curve[c].across;
        if (face.box_axis >= 0) p[face.box_axis] = face.origin[face.box_axis];
        march.push_back(p);
        march_inside.push_back(usable[c] && domain.contains(p, face) ? 1 : 0);
      }
  std::vector<Vec3> march_kept;
  for (std::size_t k = 0; k < march.size(); ++k)
    if (march_inside[k]) march_kept.push_back(march[k].cwiseMax(domain.box.lo).cwiseMin(domain.box.hi));
  const std::vector<double> march_values = values_at(surface, march_kept);
  std::vector<double> along(march.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0, m = 0; k < march.size(); ++k)
    if (march_inside[k]) along[k] = march_values[m++];
  for (std::size_t c = 0; c < curve.size(); ++c) {
    if (!usable[c]) continue;
    double width = std::numeric_limits<double>::infinity();
    for (int side = 0; side < 2; ++side) {
      const std::size_t base = (c * 2 + static_cast<std::size_t>(side)) * steps;
      for (int s = 0; s < steps; ++s) {
        const std::size_t k = base + static_cast<std::size_t>(s);
        const double distance = (s + 1) * step;
        if (!march_inside[k]) {
          // Left the face: a feature only when the curve does not end on that border nearby.
          const auto border = domain.violated(march[k], face);
          if (border && !curve_ends_near(surface, face, domain, march[k], *border, 3.0 * distance))
            width = std::min(width, distance);
          break;
        }
        // Back across f = 0: another piece of the cut (or the same curve turning back).
        if ((along[k] < 0.0) == (side == 0)) {
          width = std::min(width, distance);
          break;
        }
      }
    }
    double size = params.turn / std::max(curve[c].curvature, 1e-300);
    size = std::min(size, params.width * width);
    size = std::max(size, smallest);
    if (size < params.relevant * edge) sources.push_back({curve[c].point, size});
  }
}

}  // namespace

GradedSizes cut_feature_sizes(const Surface& surface, const Box& box, const ConvexRegion& region, double edge,
                              double smallest, const CutFeatureParams& params) {
  return GradedSizes(cut_feature_sources(surface, box, region, edge, smallest, params), edge, params.grading);
}

std::vector<SizeSource> cut_feature_sources(const Surface& surface, const Box& box,
                                            const ConvexRegion& region, double edge, double smallest,
                                            const CutFeatureParams& params) {
  // Without interval enclosures (a C++ callable) every face would cost (side / (edge / 4))^2 values of f
  // even where the surface is far away: such surfaces are not searched.
  if (!surface.bound(box)) return {};
  const Domain domain{box, cut_planes(region), 1e-9 * box.diagonal()};
  // The faces in parallel, their sources gathered in the faces' order.
  const std::vector<CuttingFace> faces = cutting_faces(box, domain);
  std::vector<std::vector<SizeSource>> by_face(faces.size());
  tbb::parallel_for(std::size_t{0}, faces.size(), [&](std::size_t k) {
    face_sources(surface, faces[k], domain, edge, smallest, params, by_face[k]);
  });
  std::vector<SizeSource> sources;
  for (const std::vector<SizeSource>& s : by_face) sources.insert(sources.end(), s.begin(), s.end());
  return sources;
}

}  // namespace isopatch
