// One smooth solid cut by planes and closed by planar caps (cut_and_caps.hpp).
#include "api/cut_and_caps.hpp"

#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/topology.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "api/crease_meshing.hpp"
#include "api/facet_polygons.hpp"
#include "api/planar_caps.hpp"
#include "api/task_arena_run.hpp"
#include "csg/face_set.hpp"

namespace isopatch {

namespace {

/// Refuses caps that could hold more vertices than Settings::max_vertices (the faces' whole areas at the
/// equilateral lattice's density): the smooth mesher's own estimate covers the cut surface.
void check_cap_size(const ConvexRegion& planes, const Box& box, double edge, std::size_t max_vertices) {
  if (max_vertices == 0) return;
  double area = 0.0;
  for (const FacetPolygon& facet : facet_polygons(planes, box))
    for (std::size_t k = 0; k + 2 < facet.corners.size(); ++k)
      area += 0.5 *
              (facet.corners[k + 1] - facet.corners[0]).cross(facet.corners[k + 2] - facet.corners[0]).norm();
  const double vertices = area / (edge * edge * std::sqrt(3.0) / 2.0);
  if (vertices <= static_cast<double>(max_vertices)) return;
  char text[256];
  std::snprintf(text, sizeof text,
                "the caps would have about %.3g vertices at edge length %.3g, more than the vertex budget of "
                "%zu: give a longer edge length or a larger budget",
                vertices, edge, max_vertices);
  throw LimitError(text, "max_vertices");
}

}  // namespace

/// Whether the polyhedron of `planes` is bounded, has a face, and lies in `box` (to `margin`).
bool polyhedron_inside(const ConvexRegion& planes, const Box& box, double margin) {
  const Box far{box.lo - box.size(), box.hi + box.size()};
  bool any = false;
  for (const FacetPolygon& facet : facet_polygons(planes, far)) {
    for (int across : facet.across)
      if (across < 0) return false;
    for (const Vec3& p : facet.corners)
      if (!box.contains(p, margin)) return false;
    any = any || !facet.corners.empty();
  }
  return any;
}

/// Whether one of the first `capped` planes bounds a face of the polyhedron of `planes` inside `box`.
bool polyhedron_meets(const ConvexRegion& planes, std::size_t capped, const Box& box) {
  const std::vector<FacetPolygon> facets = facet_polygons(planes, box);
  for (std::size_t i = 0; i < capped; ++i)
    if (!facets[i].corners.empty()) return true;
  return false;
}

Settings cut_settings(const CappedPart& part, const Settings& settings) {
  const Box& box = part.box;
  const std::size_t capped = part.capped;
  const ConvexRegion own(part.planes.begin(), part.planes.begin() + static_cast<std::ptrdiff_t>(capped));
  Settings open = settings;
  open.box = box;
  // The planes meet g = 0 inside the box: where a plane lies on a face of the box (a part meshed in its
  // own box), the cut is made in a box grown by two edges so that the box's faces cut nothing; the edge
  // length stays that of the given box.
  const double edge = default_edge_length(settings, box);
  if (part.closed && !polyhedron_inside(own, box, -2.0 * edge)) {
    if (!settings.edge_length) open.edge_length = edge;
    open.box = Box{box.lo - Vec3::Constant(2.0 * edge), box.hi + Vec3::Constant(2.0 * edge)};
  }
  open.region = part.planes;
  open.creases = Creases::Off;
  return open;
}

void check_caps_fit(const CappedPart& part, const Settings& settings) {
  const ConvexRegion own(part.planes.begin(), part.planes.begin() + static_cast<std::ptrdiff_t>(part.capped));
  check_cap_size(own, part.box, default_edge_length(settings, part.box), settings.max_vertices);
}

Mesh mesh_cut_and_caps(const CappedPart& part, const Settings& settings, MeshStats* stats, double analysis) {
  check_caps_fit(part, settings);
  Mesh mesh = part.smooth ? mesh_surface(*part.smooth, cut_settings(part, settings), stats) : Mesh{};
  return close_cut_with_caps(std::move(mesh), part, settings, stats, analysis);
}

Mesh close_cut_with_caps(Mesh mesh, const CappedPart& part, const Settings& settings, MeshStats* stats,
                         double analysis) {
  const SurfacePtr& smooth = part.smooth;
  const ConvexRegion& planes = part.planes;
  const std::size_t capped = part.capped;
  const Box& box = part.box;
  const ConvexRegion own(planes.begin(), planes.begin() + static_cast<std::ptrdiff_t>(capped));
  const Settings open = cut_settings(part, settings);
  const double edge = default_edge_length(settings, box);
  const auto caps_start = std::chrono::steady_clock::now();
  const Box& cut_box = *open.box;
  std::vector<SurfacePtr> faces;
  if (smooth) faces.push_back(smooth);
  for (const HalfSpace& h : own) faces.push_back(plane_surface(Vec3(h.a, h.b, h.c), -h.d, box));
  AngleRepair repair;
  const CapReport caps = run_in_task_arena(settings, stats, [&] {
    CapReport added = close_with_caps(mesh, smooth.get(), planes, capped, cut_box, edge,
                                      kCapOnPlane * box.diagonal(), settings);
    // Triangles at the creases, which both sides' clean-ups hold, brought over the floor on the faces;
    // the vertices on the box's faces or the region's planes stay there.
    std::vector<std::uint8_t> held(mesh.vertex_count(), 0);
    for (std::size_t v = 0; v < held.size(); ++v) {
      const Vec3& p = mesh.positions[v];
      bool on_cut = !box.contains(p, -kCapOnPlane * box.diagonal());
      for (std::size_t j = capped; j < planes.size() && !on_cut; ++j)
        on_cut = std::abs(plane_value(planes[j], p)) <= kCapOnPlane * box.diagonal();
      held[v] = on_cut ? 1 : 0;
    }
    repair = repair_crease_angles(mesh, faces, box, &held);
    return added;
  });
  const TopologyReport topology = analyze_topology(mesh);
  const std::size_t open_edges = caps.open_edges + caps.open_cap_edges;
  if (topology.boundary_edges != open_edges || !topology.manifold() || !topology.consistently_oriented())
    throw CreaseError("the capped shape's mesh is not a closed 2-manifold (" +
                      std::to_string(topology.boundary_edges) +
                      " boundary edges where the box and region cut " + std::to_string(open_edges) + ", " +
                      std::to_string(topology.non_manifold_edges + topology.non_manifold_vertices) +
                      " non-manifold places): a cap plane tangent to the surface or a feature narrower "
                      "than an edge; a smaller --edge-length, or --creases off for a smooth mesh");
  const double capping = std::chrono::duration<double>(std::chrono::steady_clock::now() - caps_start).count();
  if (stats) {
    CreaseStats c;
    c.faces = (smooth ? 1 : 0) + caps.caps;
    c.pieces = c.faces;
    c.caps = caps.caps;
    c.crease_vertices = caps.crease_vertices;
    c.repair_moves = repair.moved;
    c.seconds = analysis + capping;
    stats->creases = c;
    stats->seconds += c.seconds;
    stats->times.add("creases", analysis);
    stats->times.add("caps", capping);
    stats->vertices = mesh.vertex_count();
    stats->triangles = mesh.triangle_count();
  }
  return mesh;
}

}  // namespace isopatch
