// A smooth solid capped by a convex polyhedron, meshed as a cut surface and its caps
// (capped_meshing.hpp).
#include "api/capped_meshing.hpp"

#include <isopatch/isopatch.hpp>

#include <chrono>
#include <utility>
#include <vector>

#include "api/capped_curved_cut.hpp"
#include "api/crease_meshing.hpp"
#include "api/cut_and_caps.hpp"
#include "api/facet_polygons.hpp"
#include "csg/capped_shape.hpp"
#include "projection/convex_meshing.hpp"

namespace isopatch {

namespace {

/// Whether every corner of the polyhedron `inner` lies inside `outer` by at least `clearance`.
bool strictly_inside(const ConvexRegion& inner, const ConvexRegion& outer, const Box& box, double clearance) {
  for (const FacetPolygon& facet : facet_polygons(inner, box))
    for (const Vec3& p : facet.corners)
      for (const HalfSpace& h : outer)
        if (plane_value(h, p) > -clearance) return false;
  return true;
}

/// A lattice shelled by its box (split_shelled_shape): the outer polyhedron's caps, and the hollows
/// inside the inner one (the capped solid -g < 0 there) turned inside out; nullopt when f is no such
/// shape, a region or cells are given, or the inner polyhedron is not clear of the outer one.
std::optional<std::vector<CappedPart>> shelled_parts(const Surface& surface, const Settings& settings,
                                                     const Box& box) {
  if (!settings.region.empty()) return std::nullopt;
  const std::optional<ShelledShape> shape = split_shelled_shape(surface, box);
  if (!shape || !polyhedron_inside(shape->outer, box, kCapOnPlane * box.diagonal()) ||
      !strictly_inside(shape->inner, shape->outer, box, kCapOnPlane * box.diagonal()))
    return std::nullopt;
  Settings plain = settings;
  plain.box = box;
  plain.frame.reset();
  std::optional<Vec3> leaves;
  if (analyse_creases(*shape->hollow, plain, &leaves) || leaves) return std::nullopt;
  std::vector<CappedPart> parts;
  parts.push_back({nullptr, shape->outer, shape->outer.size(), true, box, false});
  parts.push_back({shape->hollow, shape->inner, shape->inner.size(), true, box, true});
  return parts;
}

}  // namespace

std::optional<std::vector<CappedPart>> split_capped_parts(const Surface& surface, const Settings& settings) {
  if (settings.creases == Creases::Off || settings.method != Method::Projection || !settings.cells.empty() ||
      !surface.expression())
    return std::nullopt;
  // A region decides the box when none is given (as for any surface: convex_meshing.hpp).
  const Box box =
      settings.box ? *settings.box : convex_meshing_box(surface, settings).value_or(surface.box());
  std::optional<CappedShape> shape = split_capped_shape(surface, box);
  if (!shape) return shelled_parts(surface, settings, box);
  // The part's planes, then the region's (unit normals): the region cuts the part open like the box.
  const std::size_t capped = shape->planes.size();
  ConvexRegion planes = shape->planes;
  for (const HalfSpace& h : settings.region) {
    const double n = Vec3(h.a, h.b, h.c).norm();
    planes.push_back({h.a / n, h.b / n, h.c / n, h.d / n});
  }
  // A polyhedron that leaves the box (or the region) is cut open by it: the part's boundary lies there.
  const bool closed =
      settings.region.empty() && polyhedron_inside(shape->planes, box, kCapOnPlane * box.diagonal());
  if (!closed && !polyhedron_meets(planes, capped, box)) return std::nullopt;
  const SurfacePtr& smooth = shape->smooth;
  // A polyhedron is the general crease path's, except in a rotated frame or cut open by the box, which
  // that path cannot take: its caps alone mesh it there.
  if (!smooth && closed && !settings.frame) return std::nullopt;
  Settings plain = settings;
  plain.box = box;
  plain.frame.reset();
  plain.region.clear();
  // g with creases of its own (struts joined by min, say), in the box or leaving it, is a shape for the
  // general crease path (which says so when it rounds them): its smooth mesh here would round them
  // silently.
  std::optional<Vec3> leaves;
  if (smooth && (analyse_creases(*smooth, plain, &leaves) || leaves)) return std::nullopt;
  return std::vector<CappedPart>{{smooth, planes, capped, closed, box, false}};
}

Mesh append_capped_part(Mesh mesh, const Mesh& part, bool reversed) {
  const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
  for (const Triangle& t : part.triangles)
    mesh.triangles.push_back(reversed ? Triangle{t[0] + offset, t[2] + offset, t[1] + offset}
                                      : Triangle{t[0] + offset, t[1] + offset, t[2] + offset});
  return mesh;
}

std::optional<Mesh> mesh_capped_shape(const Surface& surface, const Settings& settings, MeshStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  const std::optional<std::vector<CappedPart>> parts = split_capped_parts(surface, settings);
  if (!parts) return std::nullopt;
  const double analysis = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (parts->size() == 1) return mesh_cut_and_caps(parts->front(), settings, stats, analysis);
  // A shell: the outer polyhedron's caps (their statistics added), then the hollows (the run's own).
  MeshStats outer_stats;
  Mesh mesh = mesh_cut_and_caps((*parts)[0], settings, &outer_stats, 0.0);
  mesh = append_capped_part(std::move(mesh), mesh_cut_and_caps((*parts)[1], settings, stats, analysis),
                            (*parts)[1].reversed);
  if (stats && stats->creases && outer_stats.creases) {
    stats->creases->caps += outer_stats.creases->caps;
    stats->creases->faces += outer_stats.creases->faces;
    stats->creases->pieces += outer_stats.creases->pieces;
    stats->creases->crease_vertices += outer_stats.creases->crease_vertices;
    stats->vertices = mesh.vertex_count();
    stats->triangles = mesh.triangle_count();
  }
  return mesh;
}

std::optional<Mesh> mesh_capped_complement(const Surface& surface, const Settings& settings,
                                           MeshStats* stats) {
  const SurfacePtr minus = union_complement(surface, settings.box.value_or(surface.box()));
  if (!minus) return std::nullopt;
  std::optional<Mesh> mesh = mesh_capped_curved_cut(*minus, settings, stats);
  if (!mesh) mesh = mesh_capped_shape(*minus, settings, stats);
  if (!mesh) return std::nullopt;
  for (Triangle& t : mesh->triangles) std::swap(t[1], t[2]);
  return mesh;
}

}  // namespace isopatch
