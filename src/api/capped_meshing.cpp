// A smooth solid capped by a convex polyhedron, meshed as a cut surface and its caps
// (capped_meshing.hpp).
#include "api/capped_meshing.hpp"

#include <isopatch/isopatch.hpp>

#include <chrono>
#include <utility>

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
std::optional<Mesh> mesh_shelled(const Surface& surface, const Settings& settings, const Box& box,
                                 MeshStats* stats, std::chrono::steady_clock::time_point start) {
  if (!settings.region.empty()) return std::nullopt;
  const std::optional<ShelledShape> shape = split_shelled_shape(surface, box);
  if (!shape || !polyhedron_inside(shape->outer, box, kCapOnPlane * box.diagonal()) ||
      !strictly_inside(shape->inner, shape->outer, box, kCapOnPlane * box.diagonal()))
    return std::nullopt;
  Settings plain = settings;
  plain.box = box;
  plain.frame.reset();
  if (analyse_creases(*shape->hollow, plain)) return std::nullopt;
  const double analysis = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  MeshStats outer_stats;
  Mesh mesh =
      mesh_cut_and_caps({nullptr, shape->outer, shape->outer.size(), true, box}, settings, &outer_stats, 0.0);
  const Mesh hollows = mesh_cut_and_caps({shape->hollow, shape->inner, shape->inner.size(), true, box},
                                         settings, stats, analysis);
  const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), hollows.positions.begin(), hollows.positions.end());
  for (const Triangle& t : hollows.triangles)
    mesh.triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
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

}  // namespace

std::optional<Mesh> mesh_capped_shape(const Surface& surface, const Settings& settings, MeshStats* stats) {
  if (settings.creases == Creases::Off || settings.method != Method::Projection || !settings.cells.empty() ||
      !surface.expression())
    return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  // A region decides the box when none is given (as for any surface: convex_meshing.hpp).
  const Box box =
      settings.box ? *settings.box : convex_meshing_box(surface, settings).value_or(surface.box());
  std::optional<CappedShape> shape = split_capped_shape(surface, box);
  if (!shape) return mesh_shelled(surface, settings, box, stats, start);
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
  // g with creases of its own (struts joined by min, say) is a shape for the general crease path.
  if (smooth && analyse_creases(*smooth, plain)) return std::nullopt;
  const double analysis = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return mesh_cut_and_caps({smooth, planes, capped, closed, box}, settings, stats, analysis);
}

}  // namespace isopatch
