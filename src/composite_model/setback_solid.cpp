/// \file setback_solid.cpp
/// Convex solid -> faces, edge blends and setback vertex blends (setback_solid.hpp).
#include "composite_model/setback_solid.hpp"
#include "composite_model/line_meeting.hpp"

#include "composite_model/composite_checks.hpp"
#include "composite_model/ipatch_surface.hpp"
#include "composite_model/patch_validity.hpp"
#include "composite_model/quadric.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <tuple>

namespace isopatch {

namespace {

/// Tolerance of the planarity and convexity tests, relative to the largest coordinate (at least 1): far
/// above the rounding of a plane through a face's centroid, far below any real non-planarity or dent.
constexpr double kSetbackShapeTolerance = 1e-9;
/// An edge is flat when the cosine between its faces' unit normals is within this of 1 (an angle under
/// about 0.0026 degrees): its blend's arc shrinks to nearly a point, and the normals' rounding is ~1e-16.
constexpr double kSetbackFlatEdgeTolerance = 1e-9;
/// Margin of the composite's box, as a fraction of the diagonal of the curves and vertices: the rounded
/// solid lies inside its vertices' hull, so the margin only keeps the surfaces clear of the box's faces
/// (chosen empirically).
constexpr double kSetbackBoxMargin = 0.1;
/// A boundary curve of a vertex blend counts as running outside another side's bound beyond this
/// fraction of the blend's reach: the same value as check_patch_validity's (of the size), far above
/// rounding where a curve touches a bound, far below a real exit (0.041 beyond for a setback of 0.45).
constexpr double kSetbackExitTolerance = 1e-9;
/// The cheaper validity check that scores each candidate reference point: 8 x 8 lines of 96 steps
/// instead of 20 x 20 of 240, about 16 times cheaper, for up to 29 candidates and 6 weight trials; the
/// full check still runs on the result when it is meshed (shape_warnings). Chosen empirically.
constexpr int kSetbackTrialLinesPerAxis = 8;
constexpr int kSetbackTrialStepsPerLine = 96;
/// Candidate reference points on the mean face normal through the centroid: steps of 4% of the patch
/// size, 10 each way (up to 40%), enough for a steep apex outward and a long setback inward
/// (docs/ipatch.md); finer steps or a longer reach cost a patch and a check each. Chosen empirically.
constexpr double kSetbackShiftStep = 0.04;
constexpr int kSetbackShiftSteps = 10;
/// Candidates on the way from the centroid to the vertex, in tenths of the way, up to 8 tenths: the vertex
/// itself cannot be one (its face ribbons are 0 and its blend cylinders positive, and rule A needs every
/// ribbon negative); where to stop short of it was chosen empirically.
constexpr double kSetbackVertexFractionDivisor = 10.0;
constexpr int kSetbackVertexSteps = 8;
/// Bulges under this fraction of the size score as none, so that rounding-level values (the patch meets
/// its face planes tangentially along the trimlines) do not rank candidates; far below the check's
/// bulge_tolerance (1e-3 of the size). Chosen empirically.
constexpr double kSetbackBulgeNoise = 1e-12;
/// Weight factors tried on the face sides (the arcs keep 1) at the best point when no candidate point
/// is perfect: half and twice first, then a quarter and four times, the milder change first (chosen
/// empirically).
constexpr std::array<double, 4> kSetbackFaceSideFactors = {0.5, 2.0, 0.25, 4.0};
/// Floor of a side's chord, as a fraction of the size, when the chords are tried as weight factors:
/// keeps a degenerate side's factor positive and its inverse finite (rule A needs d_i > 0).
constexpr double kSetbackChordFloor = 1e-12;

using Id = std::uint32_t;
std::string one_based(Id v) {
  return std::to_string(v + 1);
}

/// The pieces every patch of the solid refers to, keyed by the vertices and faces they belong to.
struct Pieces {
  std::vector<ConicArc> curves;
  std::map<std::tuple<Id, Id, Id>, Vec3> corner;       ///< (vertex, far end of the edge, face) -> corner
  std::map<std::pair<Id, Id>, Id> arc;                 ///< (vertex, far end) -> the edge blend's arc there
  std::map<std::pair<Id, Id>, Id> face_curve;          ///< (vertex, face) -> trimline
  std::map<std::pair<Id, Id>, SurfacePtr> face_bound;  ///< (vertex, face) -> the trimline's bound, toward v
  std::map<std::tuple<Id, Id, Id>, Id> springline;     ///< (lower vertex, higher vertex, face) -> segment
  std::map<std::pair<Id, Id>, Vec3> axis_point;        ///< (vertex, far end) -> the blend axis at the vertex
};

/// Adds the side that runs along `curve` from `from` (which must be one of its ends).
void add_side(CompositePatch& patch, const std::vector<ConicArc>& curves, Id curve, const Vec3& from,
              const Vec3& direction) {
  const bool reversed = curves[curve].start != from;
  if (reversed && curves[curve].end != from)
    throw Error(ErrorKind::Internal, patch.name + ": sides do not chain");
  patch.sides.push_back({curve, reversed});
  patch.corner_directions.push_back(direction);
}

SurfacePtr quadric(const std::string& name, const Box& box, const Quadric& q) {
  return std::make_shared<QuadricSurface>(name, box, q);
}

/// The vertex blend's weights: reference points from the centroid of its corners outward along the
/// mean face normal m (steps of 4% of the patch size, up to 40%), then inward, then toward the vertex,
/// each with every bound positive and every ribbon negative, scored by the lines of measure_patch
/// (fewest that meet the patch twice, then the least bulge above a face plane); the first best wins,
/// and the search stops at one with neither. A steep apex needs the outward shift: through the
/// centroid its patch dips and grows an extra sheet; a long setback needs the inward one, as the
/// centroid falls inside a trimline's cylinder.
IPatchWeights choose_weights(const CompositePatch& patch, const std::vector<SurfacePtr>& ribbons,
                             const std::vector<ConicArc>& curves, const Box& box, const Vec3& centroid,
                             const Vec3& m, const Vec3& vertex, double size) {
  Composite trial;
  trial.box = box;
  trial.curves = curves;
  std::optional<IPatchWeights> best;
  PatchShape best_shape;
  ValidityOptions quick;
  quick.lines_per_axis = kSetbackTrialLinesPerAxis;
  quick.steps_per_line = kSetbackTrialStepsPerLine;
  // Outward first (0, 4%, ..., 40%), then inward (-4%, ..., -40%), then toward the vertex.
  std::vector<Vec3> candidates;
  for (int k = 0; k <= kSetbackShiftSteps; ++k)
    candidates.push_back(centroid + (kSetbackShiftStep * k * size) * m);
  for (int k = 1; k <= kSetbackShiftSteps; ++k)
    candidates.push_back(centroid - (kSetbackShiftStep * k * size) * m);
  for (int k = 1; k <= kSetbackVertexSteps; ++k)
    candidates.push_back(centroid + (k / kSetbackVertexFractionDivisor) * (vertex - centroid));
  std::optional<Vec3> best_centre;
  double best_bend = HUGE_VAL;
  const auto perfect = [&] {
    return best && best_shape.multi_root_lines == 0 && best_shape.bulge <= 0.0 && best_bend <= kGoodBend;
  };
  const auto consider = [&](const Vec3& c, const std::vector<double>& d) {
    for (std::size_t i = 0; i < ribbons.size(); ++i) {
      if (!(patch.bounds[i]->value(c) > 0.0) || !(ribbons[i]->value(c) < 0.0)) return;
    }
    IPatchWeights w = rule_a_weights(ribbons, patch.bounds, c, d, patch.name);
    CompositePatch candidate = patch;
    candidate.surface = std::make_shared<IPatchSurface>(patch.name, box, ribbons, patch.bounds, w);
    trial.patches = {candidate};
    const PatchShape shape = measure_patch(trial, 0, quick);
    const double bend = measure_boundary_bend(trial, 0).worst_angle;
    const bool folds = bend > kFoldBend, best_folds = best_bend > kFoldBend;
    const auto key = [&](int lines, bool fold, double bulge, double b) {
      return std::make_tuple(lines, fold, bulge > kSetbackBulgeNoise * size ? bulge : 0.0, b);
    };
    if (!best || key(shape.multi_root_lines, folds, shape.bulge, bend) <
                     key(best_shape.multi_root_lines, best_folds, best_shape.bulge, best_bend)) {
      best = w;
      best_shape = shape;
      best_centre = c;
      best_bend = bend;
    }
  };
  for (const Vec3& c : candidates) {
    consider(c, {});
    if (perfect()) return *best;
  }
  if (!best) return rule_a_weights(ribbons, patch.bounds, centroid, {}, patch.name);  // throws, saying why
  // Then the weight factors at the best point: the face sides (odd) lighter or heavier than the arcs,
  // or each side weighted by its curve's chord or its inverse.
  const Vec3 c = *best_centre;
  const std::size_t n = ribbons.size();
  for (double f : kSetbackFaceSideFactors) {
    std::vector<double> d(n, 1.0);
    for (std::size_t i = 1; i < n; i += 2) d[i] = f;
    consider(c, d);
    if (perfect()) return *best;
  }
  std::vector<double> chord(n), inverse(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ConicArc& a = curves[patch.sides[i].curve];
    chord[i] = std::max((a.end - a.start).norm(), kSetbackChordFloor * size);
    inverse[i] = 1.0 / chord[i];
  }
  consider(c, chord);
  consider(c, inverse);
  return *best;
}

}  // namespace

Composite build_setback_solid(const SetbackSolid& solid) {
  if (auto problem = find_topology_problem(solid.mesh)) throw InputError(problem->message);
  if (!(solid.radius > 0.0) || !(solid.setback > 0.0) || !std::isfinite(solid.radius) ||
      !std::isfinite(solid.setback)) {
    throw InputError("the blend radius and the setback must be positive");
  }
  PolygonMesh mesh = solid.mesh;
  if (signed_volume(mesh) < 0.0) {
    for (auto& f : mesh.faces) std::reverse(f.begin(), f.end());
  }
  const std::size_t nv = mesh.vertices.size(), nf = mesh.faces.size();
  double extent = 0.0;
  for (const Vec3& p : mesh.vertices) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  const double tol = kSetbackShapeTolerance * std::max(extent, 1.0);
  std::vector<Affine> planes(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    if (2 * mesh.faces[f].size() > kMaxFaceSides) {
      throw InputError("face " + one_based(Id(f)) + " has " + std::to_string(mesh.faces[f].size()) +
                       " vertices: a trimmed face has twice as many sides, at most " +
                       std::to_string(kMaxFaceSides) + " (8 vertices)");
    }
    Vec3 c = Vec3::Zero();
    for (Id v : mesh.faces[f]) c += mesh.vertices[v];
    planes[f] = plane_through(c / static_cast<double>(mesh.faces[f].size()), newell_normal(mesh, f));
    for (Id v : mesh.faces[f]) {
      if (std::abs(planes[f](mesh.vertices[v])) > tol)
        throw InputError("face " + one_based(Id(f)) + " is not planar");
    }
    for (std::size_t v = 0; v < nv; ++v) {
      if (planes[f](mesh.vertices[v]) > tol) {
        throw InputError("the solid is not convex: vertex " + one_based(Id(v)) +
                         " lies outside the plane of face " + one_based(Id(f)) +
                         " (concave and mixed vertices are not supported)");
      }
    }
  }
  const auto edges = half_edges(mesh);
  std::map<std::pair<Id, Id>, double> radius;
  for (const auto& e : solid.edge_radii) {
    if (!edges.count({e.a, e.b}) && !edges.count({e.b, e.a})) {
      throw InputError("vertices " + one_based(e.a) + " and " + one_based(e.b) +
                       " are not joined by an edge");
    }
    if (!(e.radius > 0.0)) throw InputError("a blend radius must be positive");
    radius[{std::min(e.a, e.b), std::max(e.a, e.b)}] = e.radius;
  }
  const auto radius_of = [&](Id a, Id b) {
    const auto it = radius.find({std::min(a, b), std::max(a, b)});
    return it == radius.end() ? solid.radius : it->second;
  };
  std::vector<double> setback(nv, solid.setback);
  for (const auto& s : solid.vertex_setbacks) {
    if (s.vertex >= nv || !(s.setback > 0.0))
      throw InputError("a vertex setback must name a vertex and be positive");
    setback[s.vertex] = s.setback;
  }
  const std::vector<VertexFan> fans = vertex_fans(mesh);
  const auto normal = [&](Id f) { return planes[f].n; };

  Pieces pc;
  // Corners, arcs and axis points, per vertex and edge.
  for (Id v = 0; v < nv; ++v) {
    const VertexFan& fan = fans[v];
    const std::size_t n = fan.faces.size();
    if (2 * n > kMaxFaceSides) {
      throw InputError("vertex " + one_based(v) + " has " + std::to_string(n) +
                       " edges: a vertex blend has at most " + std::to_string(kMaxFaceSides) +
                       " sides (8 edges)");
    }
    const Vec3 pv = mesh.vertices[v];
    for (std::size_t i = 0; i < n; ++i) {
      const Id w = fan.neighbours[i];
      const Id before = fan.faces[(i + n - 1) % n], after = fan.faces[i];
      const Vec3 a = normal(before), b = normal(after);
      if (!(a.dot(b) < 1.0 - kSetbackFlatEdgeTolerance)) {
        throw InputError("the edge " + one_based(v) + "-" + one_based(w) +
                         " is flat (its faces are coplanar)");
      }
      const double length = (mesh.vertices[w] - pv).norm();
      const Vec3 e = (mesh.vertices[w] - pv) / length;
      const double r = radius_of(v, w), s = setback[v];
      if (!(s + setback[w] < length)) {
        throw InputError("edge " + one_based(v) + "-" + one_based(w) + ": the setbacks at its ends (" +
                         std::to_string(s) + " + " + std::to_string(setback[w]) + ") overlap on its length " +
                         std::to_string(length));
      }
      const Vec3 p = pv - r * (a + b) / (1.0 + a.dot(b));
      const Vec3 corner_before = p + r * a + s * e, corner_after = p + r * b + s * e;
      pc.corner[{v, w, before}] = corner_before;
      pc.corner[{v, w, after}] = corner_after;
      pc.axis_point[{v, w}] = p;
      pc.arc[{v, w}] = Id(pc.curves.size());
      pc.curves.push_back({corner_before, pv + s * e, corner_after,
                           std::cos(0.5 * std::acos(std::clamp(a.dot(b), -1.0, 1.0)))});
    }
  }
  // Springline segments, per edge and face (from the lower-numbered vertex).
  for (const auto& [he, where] : edges) {
    const auto [a, b] = he;
    if (a > b) continue;
    for (Id f : {where.first, edges.at({b, a}).first}) {
      pc.springline[{a, b, f}] = Id(pc.curves.size());
      const Vec3 s = pc.corner.at({a, b, f}), t = pc.corner.at({b, a, f});
      pc.curves.push_back({s, 0.5 * (s + t), t, 1.0});
    }
  }
  // Face trimlines at each vertex: from the springline of edge i to that of edge i+1 in face i.
  std::vector<std::tuple<Id, Id, Quadric>> trim_bounds;  // (vertex, face, bound toward the vertex)
  for (Id v = 0; v < nv; ++v) {
    const VertexFan& fan = fans[v];
    const std::size_t n = fan.faces.size();
    const Vec3 pv = mesh.vertices[v];
    for (std::size_t i = 0; i < n; ++i) {
      const Id f = fan.faces[i], w0 = fan.neighbours[i], w1 = fan.neighbours[(i + 1) % n];
      const Vec3 a0 = pc.corner.at({v, w0, f}), b0 = pc.corner.at({v, w1, f});
      const Vec3 e0 = (mesh.vertices[w0] - pv).normalized(), e1 = (mesh.vertices[w1] - pv).normalized();
      double t = 0.0, u = 0.0;
      if (!meet(e0, e1, b0 - a0, t, u) || !(t < -tol) || !(u < -tol)) {
        throw InputError("vertex " + one_based(v) + ": the setback " + std::to_string(setback[v]) +
                         " is too small for face " + one_based(f) +
                         " (its springlines meet farther from the vertex)");
      }
      const Vec3 q = a0 + t * e0;
      const Vec3 fn = normal(f);
      Affine l3 = plane_through(a0, (b0 - a0).cross(fn));
      if (l3(pv) < 0.0) l3 = -l3;
      Quadric bound = Quadric::from(l3);
      ConicArc curve{a0, 0.5 * (a0 + b0), b0, 1.0};
      if (solid.conic_face_curves) {
        Affine l1 = plane_through(a0, e0.cross(fn));
        if (l1(b0) < 0.0) l1 = -l1;
        Affine l2 = plane_through(b0, e1.cross(fn));
        if (l2(a0) < 0.0) l2 = -l2;
        const double w = std::cos(
            0.5 * std::acos(std::clamp((q - a0).normalized().dot((b0 - q).normalized()), -1.0, 1.0)));
        const double l3q = l3(q);
        const double lambda = l1(b0) * l2(a0) / (4.0 * w * w * l3q * l3q);
        bound = Quadric::product(l3, l3) * lambda - Quadric::product(l1, l2);
        if (bound(pv) < 0.0) bound = bound * -1.0;
        if (!(bound(pv) > 0.0)) throw InputError("vertex " + one_based(v) + ": degenerate face trimline");
        curve = ConicArc{a0, q, b0, w};
      }
      pc.face_curve[{v, f}] = Id(pc.curves.size());
      pc.curves.push_back(curve);
      trim_bounds.emplace_back(v, f, bound);
    }
  }
  Composite out;
  out.name = solid.name;
  out.box = curves_box(pc.curves, mesh.vertices, kSetbackBoxMargin);
  for (const auto& [v, f, q] : trim_bounds) {
    pc.face_bound[{v, f}] = quadric("trimline bound", out.box, q);
  }
  std::map<std::tuple<Id, Id, Id>, Affine> spring_planes;  // (v, w, face) -> toward the edge blend
  for (const auto& [he, where] : edges) {
    const auto [a, b] = he;
    if (a > b) continue;
    const Id fa = where.first, fb = edges.at({b, a}).first;
    const Vec3 e = (mesh.vertices[b] - mesh.vertices[a]).normalized();
    const Vec3 p = pc.axis_point.at({a, b});
    Affine on_a = plane_through(p, e.cross(normal(fa)));
    if (on_a(pc.corner.at({a, b, fb})) < 0.0) on_a = -on_a;
    Affine on_b = plane_through(p, e.cross(normal(fb)));
    if (on_b(pc.corner.at({a, b, fa})) < 0.0) on_b = -on_b;
    spring_planes[{a, b, fa}] = on_a;
    spring_planes[{a, b, fb}] = on_b;
  }

  // Faces: trimline (reversed) then springline, at every vertex of the face.
  for (Id f = 0; f < nf; ++f) {
    const auto& face = mesh.faces[f];
    const std::size_t k = face.size();
    CompositePatch patch;
    patch.name = "face " + one_based(f);
    for (std::size_t j = 0; j < k; ++j) {
      const Id u = face[j], next = face[(j + 1) % k], prev = face[(j + k - 1) % k];
      add_side(patch, pc.curves, pc.face_curve.at({u, f}), pc.corner.at({u, prev, f}), normal(f));
      const Id lo = std::min(u, next), hi = std::max(u, next);
      add_side(patch, pc.curves, pc.springline.at({lo, hi, f}), pc.corner.at({u, next, f}), normal(f));
      const auto& tb = *std::static_pointer_cast<const QuadricSurface>(pc.face_bound.at({u, f}));
      if (solid.conic_face_curves) {
        Affine l3 = plane_through(pc.corner.at({u, prev, f}),
                                  (pc.corner.at({u, next, f}) - pc.corner.at({u, prev, f})).cross(normal(f)));
        if (l3(mesh.vertices[u]) > 0.0) l3 = -l3;
        patch.bounds.push_back(std::make_shared<MaxSurface>(
            patch.name + " corner", out.box, quadric("inside trimline", out.box, tb.quadric() * -1.0),
            quadric("beyond chord", out.box, Quadric::from(l3))));
      } else {
        patch.bounds.push_back(quadric(patch.name + " corner", out.box, tb.quadric() * -1.0));
      }
      patch.bounds.push_back(
          quadric(patch.name + " springline", out.box, Quadric::from(-spring_planes.at({lo, hi, f}))));
    }
    patch.surface = quadric(patch.name, out.box, Quadric::from(planes[f]));
    out.patches.push_back(std::move(patch));
  }
  // Edge blends: arc at a (reversed), springline on fb, arc at b (reversed), springline on fa.
  for (const auto& [he, where] : edges) {
    const auto [a, b] = he;
    if (a > b) continue;
    const Id fa = where.first, fb = edges.at({b, a}).first;
    CompositePatch patch;
    patch.name = "edge blend " + one_based(a) + "-" + one_based(b);
    const Vec3 e = (mesh.vertices[b] - mesh.vertices[a]).normalized();
    add_side(patch, pc.curves, pc.arc.at({a, b}), pc.corner.at({a, b, fa}), normal(fa));
    add_side(patch, pc.curves, pc.springline.at({a, b, fb}), pc.corner.at({a, b, fb}), normal(fb));
    add_side(patch, pc.curves, pc.arc.at({b, a}), pc.corner.at({b, a, fb}), normal(fb));
    add_side(patch, pc.curves, pc.springline.at({a, b, fa}), pc.corner.at({b, a, fa}), normal(fa));
    patch.bounds = {
        quadric(patch.name + " setback", out.box,
                Quadric::from(plane_through(mesh.vertices[a] + setback[a] * e, e))),
        quadric(patch.name + " springline", out.box, Quadric::from(spring_planes.at({a, b, fb}))),
        quadric(patch.name + " setback", out.box,
                Quadric::from(plane_through(mesh.vertices[b] - setback[b] * e, -e))),
        quadric(patch.name + " springline", out.box, Quadric::from(spring_planes.at({a, b, fa})))};
    patch.surface = quadric(patch.name, out.box, ball_cylinder(pc.axis_point.at({a, b}), e, radius_of(a, b)));
    out.patches.push_back(std::move(patch));
  }
  // Vertex blends: 2n sides, arc of edge i then trimline on face i.
  for (Id v = 0; v < nv; ++v) {
    const VertexFan& fan = fans[v];
    const std::size_t n = fan.faces.size();
    const Vec3 pv = mesh.vertices[v];
    CompositePatch patch;
    patch.name = "vertex blend " + one_based(v);
    std::vector<SurfacePtr> ribbons;
    Vec3 centre = Vec3::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      const Id w = fan.neighbours[i], before = fan.faces[(i + n - 1) % n], f = fan.faces[i];
      const Vec3 e = (mesh.vertices[w] - pv).normalized();
      add_side(patch, pc.curves, pc.arc.at({v, w}), pc.corner.at({v, w, before}), normal(before));
      ribbons.push_back(quadric(patch.name + " ribbon", out.box,
                                ball_cylinder(pc.axis_point.at({v, w}), e, radius_of(v, w))));
      patch.bounds.push_back(
          quadric(patch.name + " setback", out.box, Quadric::from(plane_through(pv + setback[v] * e, -e))));
      add_side(patch, pc.curves, pc.face_curve.at({v, f}), pc.corner.at({v, w, f}), normal(f));
      ribbons.push_back(quadric(patch.name + " face", out.box, Quadric::from(planes[f])));
      patch.bounds.push_back(pc.face_bound.at({v, f}));
      centre += pc.corner.at({v, w, before}) + pc.corner.at({v, w, f});
    }
    centre /= static_cast<double>(2 * n);
    {
      Composite trial;
      trial.curves = pc.curves;
      const BoundaryExit exit = measure_boundary_exit(trial, patch);
      double reach = 0.0;
      for (const PatchSide& s : patch.sides) reach = std::max(reach, (pc.curves[s.curve].start - pv).norm());
      if (exit.distance > kSetbackExitTolerance * reach) {
        const auto side_name = [&](std::size_t k) {
          return k % 2 == 0 ? "the arc of edge " + one_based(v) + "-" + one_based(fan.neighbours[k / 2])
                            : "the trimline on face " + one_based(fan.faces[k / 2]);
        };
        const auto bound_name = [&](std::size_t k) {
          return k % 2 == 0
                     ? "the setback plane of edge " + one_based(v) + "-" + one_based(fan.neighbours[k / 2])
                     : "the bound of the trimline on face " + one_based(fan.faces[k / 2]);
        };
        throw InputError("vertex " + one_based(v) + ": the setback " + std::to_string(setback[v]) +
                         " is too short for the blend radii there: " + side_name(exit.side) + " runs " +
                         std::to_string(exit.distance) + " beyond " + bound_name(exit.bound) +
                         ", so no vertex blend can reach it; use a longer setback");
      }
    }
    Vec3 m = Vec3::Zero();
    double size = 0.0;
    for (Id f : fan.faces) m += normal(f);
    for (const PatchSide& s : patch.sides) size = std::max(size, (pc.curves[s.curve].start - centre).norm());
    IPatchWeights weights =
        choose_weights(patch, ribbons, pc.curves, out.box, centre, m.normalized(), pv, 2.0 * size);
    patch.surface =
        std::make_shared<IPatchSurface>(patch.name, out.box, ribbons, patch.bounds, std::move(weights));
    out.patches.push_back(std::move(patch));
  }
  out.curves = std::move(pc.curves);
  check_composite_closed(out);
  return out;
}

}  // namespace isopatch
