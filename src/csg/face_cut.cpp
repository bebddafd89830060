/// \file face_cut.cpp
/// One cut of a part of a face by a plane (face_cut.hpp).
#include "csg/face_cut.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <utility>

#include "csg/curve_tracer.hpp"
#include "surface/curve_point.hpp"

namespace isopatch {

int PlaneCutter::node_degree(int node) const {
  int n = 0;
  for (const GraphCurve& c : graph.curves) n += (c.start == node ? 1 : 0) + (c.end == node ? 1 : 0);
  return n;
}

Plane PlaneCutter::snapped_to_nodes(Plane plane, const std::vector<const FaceCycle*>& cycles) const {
  double best = h / 3.0;
  double offset = plane.offset;
  for (const FaceCycle* c : cycles)
    for (const HalfCurve& s : c->sides) {
      const GraphCurve& curve = graph.curves[static_cast<std::size_t>(s.curve)];
      if (curve.start == curve.end) continue;  // a closed loop's node moves (cut())
      const Vec3& p = graph.nodes[static_cast<std::size_t>(curve.start)].position;
      if (std::abs(plane.at(p)) < best) {
        best = std::abs(plane.at(p));
        offset = plane.normal.dot(p);
      }
    }
  plane.offset = offset;
  return plane;
}

GraphCurve& PlaneCutter::add_seam(const std::vector<Vec3>& points, int g, const SurfacePtr& plane_fn,
                                  const Plane& plane) {
  GraphCurve seam;
  seam.points = points;
  seam.left = seam.right = g;
  seam.first = faces.function(g);
  seam.second = plane_fn;
  seam.seam = true;
  seam.plane_normal = plane.normal;
  seam.plane_offset = plane.offset;
  graph.curves.push_back(std::move(seam));
  return graph.curves.back();
}

int PlaneCutter::split_at(std::size_t c, std::size_t k, const Vec3& p) {
  auto& points = graph.curves[c].points;
  points.insert(points.begin() + static_cast<std::ptrdiff_t>(k + 1), p);
  touched.insert(static_cast<int>(c));
  return split_curve(graph, c, k + 1);
}

std::optional<int> PlaneCutter::node_on_face_curve(int g, const Vec3& p) {
  const double merge = 1e-7 * box.diagonal();
  for (std::size_t n = 0; n < graph.nodes.size(); ++n)
    if ((graph.nodes[n].position - p).norm() <= merge) return static_cast<int>(n);
  std::size_t best_c = 0, best_k = 0;
  double best = h;
  for (std::size_t c = 0; c < graph.curves.size(); ++c) {
    const GraphCurve& curve = graph.curves[c];
    if (curve.left != g && curve.right != g) continue;
    for (std::size_t k = 0; k + 1 < curve.points.size(); ++k) {
      const Vec3 a = curve.points[k], b = curve.points[k + 1];
      const double u = std::clamp((p - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300), 0.0, 1.0);
      const double d = (a + u * (b - a) - p).norm();
      if (d < best) {
        best = d;
        best_c = c;
        best_k = k;
      }
    }
  }
  if (best >= h) return std::nullopt;
  return split_at(best_c, best_k, p);
}

int PlaneCutter::cut(int g, int part, const std::vector<const FaceCycle*>& cycles, const Plane& plane) {
  const Surface& fg = *faces.function(g);
  const SurfacePtr plane_fn = plane_surface(plane.normal, plane.offset, box);
  CurvePointParams cp;
  cp.tolerance = tolerance;
  cp.max_step = h;
  cp.max_travel = h;
  // 1. Where the plane crosses the part's curves: split them there.
  std::set<int> curves;
  std::map<int, bool> reversed;  // how the part's cycle runs along each of its curves
  for (const FaceCycle* c : cycles)
    for (const HalfCurve& s : c->sides) {
      curves.insert(s.curve);
      reversed.emplace(s.curve, s.reversed);
    }
  std::vector<int> crossings;
  std::map<int, Vec3> inward;  // per crossing node: the direction into the part (left of its cycle)
  // Nodes of the part's cycles on the plane are crossings as they are; the way into the part there
  // lies between the cycle's two sides (within the piece's angle at the node).
  std::map<int, std::pair<Vec3, Vec3>> corner_sides;  // node -> (way out along the next side, way back)
  for (const FaceCycle* c : cycles)
    for (std::size_t k = 0; k < c->sides.size(); ++k) {
      const HalfCurve& in = c->sides[(k + c->sides.size() - 1) % c->sides.size()];
      const HalfCurve& out = c->sides[k];
      const int node = start_node(graph, out);
      if (std::abs(plane.at(graph.nodes[static_cast<std::size_t>(node)].position)) > 1e-9 * box.diagonal())
        continue;
      const std::vector<Vec3> po = half_points(graph, out), pi = half_points(graph, in);
      corner_sides[node] = {po[1] - po[0], pi[pi.size() - 2] - pi.back()};
      crossings.push_back(node);
    }
  for (const int c : curves) {
    std::vector<std::pair<std::size_t, Vec3>> found;
    std::vector<Vec3> along;
    const auto find = [&] {
      const auto& p = graph.curves[static_cast<std::size_t>(c)].points;
      const double on_plane = 1e-9 * box.diagonal();
      for (std::size_t k = 0; k + 1 < p.size(); ++k) {
        const double a = plane.at(p[k]), b = plane.at(p[k + 1]);
        if ((a < 0.0) == (b < 0.0)) continue;
        // A crossing at a node of the curve is that node's (below).
        if ((k == 0 && std::abs(a) <= on_plane) || (k + 2 == p.size() && std::abs(b) <= on_plane)) continue;
        const Vec3 guess = p[k] + (a / (a - b)) * (p[k + 1] - p[k]);
        const GraphCurve& curve = graph.curves[static_cast<std::size_t>(c)];
        const std::optional<Vec3> x = settle_on_corner(*curve.first, *curve.second, *plane_fn, guess, cp);
        if (!x) throw CreaseError("a cutting plane meets a crease tangentially near " + point_text(guess));
        found.emplace_back(k, *x);
        along.push_back((reversed[c] ? -1.0 : 1.0) * (p[k + 1] - p[k]));
      }
    };
    find();
    GraphCurve& loop = graph.curves[static_cast<std::size_t>(c)];
    if (!found.empty() && loop.start == loop.end && node_degree(loop.start) == 2) {
      // A closed loop's node is only where its trace began: the loop starts at its first crossing
      // instead, which becomes its node.
      const auto [k0, x0] = found.front();
      std::vector<Vec3> rotated{x0};
      rotated.insert(rotated.end(), loop.points.begin() + static_cast<std::ptrdiff_t>(k0 + 1),
                     loop.points.end());
      rotated.insert(rotated.end(), loop.points.begin() + 1,
                     loop.points.begin() + static_cast<std::ptrdiff_t>(k0 + 1));
      rotated.push_back(x0);
      loop.points = std::move(rotated);
      graph.nodes[static_cast<std::size_t>(loop.start)].position = x0;
      crossings.push_back(loop.start);
      inward[loop.start] = fg.value_gradient(x0).gradient.cross(along.front());
      found.clear();
      along.clear();
      find();
    }
    for (std::size_t i = found.size(); i-- > 0;) {
      const int node = split_at(static_cast<std::size_t>(c), found[i].first, found[i].second);
      crossings.push_back(node);
      inward[node] = fg.value_gradient(found[i].second).gradient.cross(along[i]);
    }
  }
  std::sort(crossings.begin(), crossings.end());
  crossings.erase(std::unique(crossings.begin(), crossings.end()), crossings.end());
  // 2. Seams from every crossing into the part, each to the crossing it ends at.
  TraceParams trace;
  trace.step = 0.25 * h;
  trace.tolerance = tolerance;
  trace.box = box;
  // The part's seams bound it too: a seam being traced stops where it crosses one (the part lies on
  // the side of each that its cycle has on its left).
  std::vector<SurfacePtr> seam_bounds;
  for (const FaceCycle* c : cycles)
    for (const HalfCurve& s : c->sides) {
      const GraphCurve& curve = graph.curves[static_cast<std::size_t>(s.curve)];
      if (!curve.seam) continue;
      const std::vector<Vec3> p = half_points(graph, s);
      const std::size_t mid = p.size() / 2;
      const Vec3 left = fg.value_gradient(p[mid]).gradient.cross(p[std::min(mid + 1, p.size() - 1)] -
                                                                 p[mid - (mid > 0 ? 1 : 0)]);
      const double sign = left.dot(curve.plane_normal) >= 0.0 ? 1.0 : -1.0;
      seam_bounds.push_back(plane_surface(sign * curve.plane_normal, sign * curve.plane_offset, box));
    }
  constexpr int kSeamOwner = 1 << 24;  // owner ids from here on name the part's seams
  trace.third_function = [&](int owner) -> const Surface& {
    return owner >= kSeamOwner ? *seam_bounds[static_cast<std::size_t>(owner - kSeamOwner)]
                               : *faces.function(owner);
  };
  trace.owner = [&](const Vec3& q) {
    for (std::size_t s = 0; s < seam_bounds.size(); ++s)
      if (seam_bounds[s]->value(q) < -tolerance) return kSeamOwner + static_cast<int>(s);
    const int owner = faces.on_shape(q, fg, kOnShapeTolerances * tolerance)
                          ? faces.boundary_face(std::array{g}, q, 1e-9 * box.diagonal())
                          : faces.face_at(q);
    return owner == g ? -1 : owner;
  };
  for (const int x : crossings) trace.targets.push_back(graph.nodes[static_cast<std::size_t>(x)].position);
  std::set<int> done;
  int seams = 0;
  for (const int x : crossings) {
    if (done.count(x)) continue;
    const Vec3 p = graph.nodes[static_cast<std::size_t>(x)].position;
    const Vec3 t = curve_tangent(fg, *plane_fn, p);
    double sign = 0.0;
    if (const auto corner = corner_sides.find(x); corner != corner_sides.end()) {
      const Vec3 n = fg.value_gradient(p).gradient.normalized();
      const auto ccw = [&](const Vec3& from, const Vec3& to) {
        const double a = std::atan2(n.dot(from.cross(to)), from.dot(to));
        return a < 0.0 ? a + 2.0 * std::numbers::pi : a;
      };
      const double inside = ccw(corner->second.first, corner->second.second);
      for (const double s : {1.0, -1.0}) {
        const double a = ccw(corner->second.first, s * t);
        if (a > 1e-6 && a < inside - 1e-6) sign = s;
      }
    } else {
      const double into = t.dot(inward[x]);
      if (std::abs(into) >= 1e-6 * inward[x].norm()) sign = into > 0.0 ? 1.0 : -1.0;
    }
    if (sign == 0.0) continue;  // the plane grazes the part here
    const TracedPath path = trace_curve(fg, *plane_fn, p, sign, trace);
    if (path.end != TraceEnd::Corner)
      throw CreaseError("a seam cutting a face into pieces cannot be traced from " + point_text(p));
    const std::optional<int> end = node_on_face_curve(g, path.points.back());
    if (!end || *end == x)
      throw CreaseError("a seam cutting a face ends away from its creases near " +
                        point_text(path.points.back()));
    GraphCurve& seam = add_seam(path.points, g, plane_fn, plane);
    seam.points.front() = p;
    seam.points.back() = graph.nodes[static_cast<std::size_t>(*end)].position;
    seam.start = x;
    seam.end = *end;
    done.insert(x);
    done.insert(*end);
    ++seams;
  }
  // 3. A part with no crease: closed seams from the coarse mesh's edges across the plane.
  std::vector<int> members;
  for (std::size_t v = 0; v < parts.part.size(); ++v)
    if (parts.part[v] == part) members.push_back(static_cast<int>(v));
  if (cycles.empty()) {
    std::vector<Vec3> traced;
    for (const int v : members)
      for (const int w : parts.neighbours[static_cast<std::size_t>(v)]) {
        if (parts.part[static_cast<std::size_t>(w)] != part) continue;
        const Vec3 a = samples.mesh.positions[static_cast<std::size_t>(v)];
        const Vec3 b = samples.mesh.positions[static_cast<std::size_t>(w)];
        if ((plane.at(a) < 0.0) == (plane.at(b) < 0.0)) continue;
        const Vec3 m = 0.5 * (a + b);
        if (std::any_of(traced.begin(), traced.end(),
                        [&](const Vec3& q) { return (q - m).norm() < 2.0 * h; }))
          continue;
        const std::optional<Vec3> start = settle_on_curve(fg, *plane_fn, m, cp);
        if (!start) continue;
        const TracedPath path = trace_curve(fg, *plane_fn, *start, 1.0, trace);
        if (path.end != TraceEnd::Closed)
          throw CreaseError("a seam round a face without creases does not close near " + point_text(*start));
        const int node = graph.node_at(*start, 0.0);
        GraphCurve& seam = add_seam(path.points, g, plane_fn, plane);
        seam.start = seam.end = node;
        traced.insert(traced.end(), path.points.begin(), path.points.end());
        ++seams;
      }
  }
  // 4. The part's vertices on either side of the plane become parts of their own.
  if (seams > 0 && !members.empty())
    parts.relabel(members, part, [&](int v, int w) {
      return (plane.at(samples.mesh.positions[static_cast<std::size_t>(v)]) < 0.0) ==
             (plane.at(samples.mesh.positions[static_cast<std::size_t>(w)]) < 0.0);
    });
  return seams;
}

}  // namespace isopatch
