/// \file csg_composite.cpp
/// A CSG shape as a composite surface (csg_composite.hpp).
#include "csg/csg_composite.hpp"

#include <isopatch/error.hpp>
#include <isopatch/expression.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>

#include "csg/crease_search.hpp"
#include "csg/face_cycles.hpp"
#include "csg/face_regions.hpp"
#include "csg/face_set.hpp"

namespace isopatch {

namespace {

/// The unit outward normal of a face's function at p.
Vec3 face_normal(const Surface& f, const Vec3& p) {
  return f.value_gradient(p).gradient.normalized();
}

/// The angle of a piece at the start of side k: between the way back along side k - 1 and side k.
double corner_angle(const CreaseGraph& g, const FaceCycle& c, std::size_t k, const Vec3& n) {
  const std::vector<Vec3> out = half_points(g, c.sides[k]);
  const std::vector<Vec3> in = half_points(g, c.sides[(k + c.sides.size() - 1) % c.sides.size()]);
  Vec3 a = out[1] - out[0], b = in[in.size() - 2] - in.back();
  a -= a.dot(n) * n;
  b -= b.dot(n) * n;
  // Measured counter-clockwise from the outgoing side to the way back, the piece on the left.
  double angle = std::atan2(n.dot(a.cross(b)), a.dot(b));
  if (angle < 0.0) angle += 2.0 * std::numbers::pi;
  return angle;
}

}  // namespace

std::optional<CsgShape> analyse_csg(const Surface& surface, const Box& box, double cell,
                                    std::optional<Vec3>* leaves_box) {
  const Expression* expression = surface.expression();
  if (!expression) return std::nullopt;
  auto face_set = std::make_shared<FaceSet>(*expression, box);
  FaceSet& faces = *face_set;
  if (!faces.has_switches()) return std::nullopt;
  CreaseSearch search = find_creases(faces, box, cell);
  if (search.leaves_box) {
    if (leaves_box) *leaves_box = search.leaves_box;
    return std::nullopt;
  }
  if (search.graph.curves.empty()) return std::nullopt;
  if (!search.tangential_contacts.empty())
    throw ShapeNotManifoldError(
        "two faces of the shape touch tangentially near " + point_text(search.tangential_contacts.front()) +
        " without crossing: the shape is not a 2-manifold there (--creases off meshes it as a "
        "smooth surface)");
  CsgShape shape;
  shape.creases = search.graph.curves.size();
  shape.corners = search.graph.nodes.size();
  shape.smooth_pairs = search.smooth_pairs;
  shape.certificate = search.certificate;
  CreaseGraph& graph = search.graph;
  for (GraphCurve& c : graph.curves)
    if (c.start == c.end) --shape.corners;  // a closed loop's node is no corner
  cut_into_discs(graph, faces, search.samples, box);
  const std::vector<FaceCycle> cycles = split_into_polygons(graph, faces);

  Composite& out = shape.composite;
  out.name = surface.name();
  out.box = box;
  std::set<int> face_ids;
  for (const GraphCurve& c : graph.curves) {
    if (c.seam) ++shape.seams;
    out.curves.push_back(
        ConicArc{c.points.front(), 0.5 * (c.points.front() + c.points.back()), c.points.back(), 1.0});
    out.traced.push_back(TracedCurve{c.points, c.first, c.second});
  }
  for (const FaceCycle& cycle : cycles) {
    face_ids.insert(cycle.face);
    CompositePatch patch;
    patch.name = "face " + std::to_string(cycle.face) + " piece " + std::to_string(out.patches.size());
    patch.surface = faces.function(cycle.face);
    patch.bounds.push_back(faces.region_bound(cycle.face));
    for (std::size_t k = 0; k < cycle.sides.size(); ++k) {
      const HalfCurve& h = cycle.sides[k];
      patch.sides.push_back({static_cast<std::uint32_t>(h.curve), h.reversed});
      const Vec3 corner = graph.nodes[static_cast<std::size_t>(start_node(graph, h))].position;
      const Vec3 n = face_normal(*patch.surface, corner);
      patch.corner_directions.push_back(n);
      if (corner_angle(graph, cycle, k, n) < kExemptCornerDegrees * std::numbers::pi / 180.0)
        ++shape.exempt_corners;
      const GraphCurve& c = graph.curves[static_cast<std::size_t>(h.curve)];
      if (c.seam) {
        // The seam's plane, facing the piece (on the left of the side).
        const std::vector<Vec3> p = half_points(graph, h);
        const std::size_t mid = p.size() / 2;
        const Vec3 t = p[std::min(mid + 1, p.size() - 1)] - p[mid == 0 ? 0 : mid - 1];
        const Vec3 left = face_normal(*patch.surface, p[mid]).cross(t);
        const double sign = left.dot(c.plane_normal) >= 0.0 ? 1.0 : -1.0;
        patch.bounds.push_back(plane_surface(sign * c.plane_normal, sign * c.plane_offset, box));
      }
    }
    out.patches.push_back(std::move(patch));
  }
  shape.faces = face_ids.size();
  for (const int face : face_ids) shape.face_functions.push_back(faces.function(face));
  shape.face_set = std::move(face_set);
  return shape;
}

}  // namespace isopatch
