/// \file control_polyhedron.cpp
/// Control polyhedron -> composite of I-patches (control_polyhedron.hpp).
#include "composite_model/control_polyhedron.hpp"
#include "composite_model/line_meeting.hpp"

#include "composite_model/composite_checks.hpp"
#include "composite_model/ipatch_surface.hpp"
#include "composite_model/patch_validity.hpp"
#include "composite_model/quadric.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <tuple>

namespace isopatch {

namespace {

using EdgeKey = std::pair<std::uint32_t, std::uint32_t>;

std::string edge_name(const EdgeKey& e) {
  return "edge " + std::to_string(e.first + 1) + "-" + std::to_string(e.second + 1);
}

/// Everything an edge gives both of its faces.
struct EdgeData {
  std::uint32_t curve = 0;
  Affine bounding;  ///< through the chord and the mean normal (either orientation)
  Quadric ribbon;   ///< negative inside, its gradient along the vertex normals at the ends
};

/// The weight of the conic (a, q, b; w) through m: with barycentric coordinates (ta, tq, tb) of m in
/// the triangle, the conic is tq^2 = 4 w^2 ta tb.
double weight_through(const Vec3& a, const Vec3& q, const Vec3& b, const Vec3& m, const std::string& what) {
  const Vec3 n = (q - a).cross(b - a);
  const double area = n.squaredNorm();
  const double ta = (q - m).cross(b - m).dot(n) / area;
  const double tq = (b - m).cross(a - m).dot(n) / area;
  const double tb = (a - m).cross(q - m).dot(n) / area;
  const double off_plane = std::abs((m - a).dot(n.normalized()));
  if (!(off_plane <= 1e-6 * (b - a).norm()) || !(ta > 0.0 && tq > 0.0 && tb > 0.0)) {
    throw InputError(what +
                     ": the point the curve must pass through is not inside the triangle of its end "
                     "points and tangent lines");
  }
  return tq / (2.0 * std::sqrt(ta * tb));
}

EdgeData build_edge(const EdgeKey& key, const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                    const ControlPolyhedron::EdgeShape* shape, std::vector<ConicArc>& curves) {
  const std::string what = edge_name(key);
  const Vec3 pv = points[key.first], pw = points[key.second];
  const Vec3 nv = normals[key.first], nw = normals[key.second];
  const Vec3 chord = pw - pv;
  const Vec3 mean = nv + nw;
  if (!(mean.norm() > 1e-9)) throw InputError(what + ": the vertex normals at its ends are opposite");
  const Vec3 nb = chord.cross(mean.normalized());
  if (!(nb.norm() > 1e-9 * chord.norm()))
    throw InputError(what + ": the mean vertex normal is parallel to it");
  EdgeData e;
  e.bounding = plane_through(pv, nb);
  const Affine tv = plane_through(pv, nv), tw = plane_through(pw, nw);
  Vec3 dv = nv.cross(nb), dw = nw.cross(nb);
  if (!(dv.norm() > 1e-9 * nb.norm()) || !(dw.norm() > 1e-9 * nb.norm())) {
    throw InputError(what + ": a vertex normal lies in the edge's bounding plane");
  }
  dv.normalize();
  dw.normalize();
  if (dv.dot(chord) < 0.0) dv = -dv;
  if (dw.dot(chord) < 0.0) dw = -dw;
  const Vec3 unit_chord = chord.normalized();
  ConicArc arc{pv, 0.5 * (pv + pw), pw, 1.0};
  if (dv.dot(unit_chord) > 1.0 - 1e-12 && dw.dot(unit_chord) > 1.0 - 1e-12 && nv.dot(nw) > 1.0 - 1e-12) {
    // Both tangent planes hold the chord and coincide: a straight edge, the tangent plane its ribbon.
    if (shape && (shape->weight || shape->through)) {
      throw InputError(what +
                       ": a straight edge (both vertex normals equal and perpendicular to it) takes no "
                       "weight or point");
    }
    e.ribbon = Quadric::from(tv);
  } else {
    double alpha = 0.0, beta = 0.0;
    if (!meet(dv, -dw, chord, alpha, beta) || !(alpha > 0.0) || !(beta > 0.0)) {
      throw InputError(what +
                       ": its vertex normals ask for an S-shaped or reflex boundary curve, which no "
                       "conic follows (change the normals with 'vn')");
    }
    const Vec3 q = pv + alpha * dv;
    double w = std::cos(0.5 * std::acos(std::clamp(dv.dot(dw), -1.0, 1.0)));
    if (shape && shape->weight) w = *shape->weight;
    if (shape && shape->through) w = weight_through(pv, q, pw, *shape->through, what);
    if (!(w > 0.0) || !std::isfinite(w)) throw InputError(what + ": the curve weight must be positive");
    arc = ConicArc{pv, q, pw, w};
    const Vec3 m = arc.point(0.5);
    const Vec3 ln = nb.cross(chord);
    const Affine l = plane_through(pv, ln);
    const double lm = l(m);
    const double lambda = tv(m) * tw(m) / (lm * lm);
    if (!(lambda > 0.0) || !std::isfinite(lambda)) {
      throw InputError(what + ": no Liming ribbon fits its curve (lambda <= 0)");
    }
    // The gradient of tv tw - lambda l^2 at pv is tw(pv) nv: orient it along the outward normal.
    const double sigma = tw(pv) < 0.0 ? -1.0 : 1.0;
    if (!(sigma * tv(pw) > 0.0) || !(std::abs(tw(pv)) > 0.0)) {
      throw InputError(what + ": its ribbon cannot face outward at both ends");
    }
    e.ribbon = liming_quadric(tv, tw, l, lambda, sigma);
  }
  e.curve = static_cast<std::uint32_t>(curves.size());
  curves.push_back(arc);
  return e;
}

Vec3 face_centroid(const PolygonMesh& mesh, std::uint32_t f) {
  Vec3 c = Vec3::Zero();
  for (std::uint32_t v : mesh.faces[f]) c += mesh.vertices[v];
  return c / static_cast<double>(mesh.faces[f].size());
}

}  // namespace

Composite build_control_polyhedron(const ControlPolyhedron& polyhedron) {
  if (auto problem = find_topology_problem(polyhedron.mesh)) throw InputError(problem->message);
  PolygonMesh mesh = polyhedron.mesh;
  if (signed_volume(mesh) < 0.0) {
    for (auto& f : mesh.faces) std::reverse(f.begin(), f.end());
  }
  const std::size_t nv = mesh.vertices.size();
  std::vector<Vec3> normals(nv, Vec3::Zero());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const Vec3 n = newell_normal(mesh, f).normalized();
    for (std::uint32_t v : mesh.faces[f]) normals[v] += n;
  }
  for (std::size_t v = 0; v < nv; ++v) {
    if (v < polyhedron.normals.size() && polyhedron.normals[v]) normals[v] = *polyhedron.normals[v];
    if (!(normals[v].norm() > 1e-9) || !normals[v].allFinite()) {
      throw InputError("vertex " + std::to_string(v + 1) + ": its normal is zero");
    }
    normals[v].normalize();
  }
  std::map<EdgeKey, const ControlPolyhedron::EdgeShape*> shapes;
  for (const auto& s : polyhedron.edges) shapes[{std::min(s.a, s.b), std::max(s.a, s.b)}] = &s;
  std::map<EdgeKey, EdgeData> edges;
  Composite out;
  out.name = polyhedron.name;
  for (const auto& face : mesh.faces) {
    for (std::size_t i = 0; i < face.size(); ++i) {
      const EdgeKey key{std::min(face[i], face[(i + 1) % face.size()]),
                        std::max(face[i], face[(i + 1) % face.size()])};
      if (edges.count(key)) continue;
      const auto shape = shapes.find(key);
      edges[key] = build_edge(key, mesh.vertices, normals, shape == shapes.end() ? nullptr : shape->second,
                              out.curves);
      if (shape != shapes.end()) shapes.erase(shape);
    }
  }
  if (!shapes.empty())
    throw InputError(edge_name(shapes.begin()->first) + " is not an edge of the polyhedron");

  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : mesh.vertices) centroid += p;
  centroid /= static_cast<double>(nv);
  std::map<std::uint32_t, const ControlPolyhedron::FaceShape*> face_shapes;
  for (const auto& s : polyhedron.faces) {
    if (s.face >= mesh.faces.size())
      throw InputError("face " + std::to_string(s.face + 1) + " does not exist");
    face_shapes[s.face] = &s;
  }
  std::vector<Vec3> centres;
  for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& face = mesh.faces[f];
    Vec3 fc = Vec3::Zero();
    double radius = 0.0;
    for (std::uint32_t v : face) {
      fc += mesh.vertices[v];
      radius += (mesh.vertices[v] - centroid).norm();
    }
    fc /= static_cast<double>(face.size());
    radius /= static_cast<double>(face.size());
    const auto shape = face_shapes.find(f);
    if (shape != face_shapes.end() && shape->second->centre) {
      centres.push_back(*shape->second->centre);
    } else if ((fc - centroid).norm() > 1e-9 * radius) {
      centres.push_back(centroid + (fc - centroid).normalized() * radius);
    } else {
      throw InputError("face " + std::to_string(f + 1) +
                       ": its centroid is the polyhedron's; give its reference point with 'face K centre'");
    }
  }
  // Reference points: the default above, or when its patch fails (its ribbons differ in sign there,
  // or some line meets the patch twice in its region), the first point along the face normal from the
  // face centroid (steps of a tenth of the face's radius, from -0.5 to 1.5) whose patch does not; when
  // none passes, the first with the fewest such lines (the validity check then reports it).
  const Box trial_box = curves_box(out.curves, centres, 1.0);
  std::map<EdgeKey, SurfacePtr> ribbons;
  for (const auto& [key, e] : edges) {
    ribbons[key] = std::make_shared<QuadricSurface>("ribbon of " + edge_name(key), trial_box, e.ribbon);
  }
  const auto build_patch = [&](std::uint32_t f, const Box& box, const Vec3& centre) {
    const auto& face = mesh.faces[f];
    const std::string name = "face " + std::to_string(f + 1);
    CompositePatch patch;
    patch.name = name;
    const Vec3 fc = face_centroid(mesh, f);
    std::vector<SurfacePtr> rib;
    for (std::size_t i = 0; i < face.size(); ++i) {
      const std::uint32_t a = face[i], b = face[(i + 1) % face.size()];
      const EdgeKey key{std::min(a, b), std::max(a, b)};
      const EdgeData& e = edges.at(key);
      Affine bound = e.bounding;
      if (bound(fc) < 0.0) bound = -bound;
      if (!(bound(fc) > 0.0))
        throw InputError(name + ": its centroid lies on the bounding plane of " + edge_name(key));
      patch.sides.push_back({e.curve, a > b});
      patch.corner_directions.push_back(normals[a]);
      patch.bounds.push_back(std::make_shared<QuadricSurface>(name + " bound " + std::to_string(i + 1), box,
                                                              Quadric::from(bound)));
      rib.push_back(ribbons.at(key));
    }
    const auto shape = face_shapes.find(f);
    const std::vector<double> d = shape != face_shapes.end() ? shape->second->d : std::vector<double>{};
    IPatchWeights weights = rule_a_weights(rib, patch.bounds, centre, d, name);
    patch.surface = std::make_shared<IPatchSurface>(name, box, rib, patch.bounds, std::move(weights));
    return patch;
  };
  Composite trial;
  trial.box = trial_box;
  trial.curves = out.curves;
  ValidityOptions quick;
  quick.lines_per_axis = 8;
  quick.steps_per_line = 96;
  for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
    const auto shape = face_shapes.find(f);
    if (shape != face_shapes.end() && shape->second->centre) continue;  // given: used as is
    const Vec3 fc = face_centroid(mesh, f);
    const Vec3 n = newell_normal(mesh, f).normalized();
    double radius = 0.0;
    for (std::uint32_t v : mesh.faces[f]) radius += (mesh.vertices[v] - fc).norm();
    radius /= static_cast<double>(mesh.faces[f].size());
    std::vector<Vec3> candidates{centres[f]};
    for (int k = -5; k <= 15; ++k) candidates.push_back(fc + (0.1 * k * radius) * n);
    // The best candidate so far: fewest lines meeting the patch twice, then no fold beside the boundary,
    // then the least bend there (measure_boundary_bend); the default is kept when it is good.
    std::optional<std::tuple<int, bool, double>> best;
    for (const Vec3& c : candidates) {
      try {
        trial.patches = {build_patch(f, trial_box, c)};
      } catch (const InputError&) {
        continue;  // outside the region, or the ribbons differ in sign there
      }
      const int lines = measure_patch(trial, 0, quick).multi_root_lines;
      const double bend = measure_boundary_bend(trial, 0).worst_angle;
      const auto key = std::make_tuple(lines, bend > kFoldBend, bend);
      if (!best || key < *best) {
        best = key;
        centres[f] = c;
      }
      if (&c == &candidates.front() && lines == 0 && bend <= kGoodBend) break;  // the default is good
    }
  }
  out.box = curves_box(out.curves, centres, 0.15);
  for (auto& [key, r] : ribbons) {
    r = std::make_shared<QuadricSurface>("ribbon of " + edge_name(key), out.box, edges.at(key).ribbon);
  }
  for (std::uint32_t f = 0; f < mesh.faces.size(); ++f)
    out.patches.push_back(build_patch(f, out.box, centres[f]));
  check_composite_closed(out);
  return out;
}

}  // namespace isopatch
