// A CSG shape cut open by planes, meshed along its creases (clipped_creases.hpp).
#include "api/clipped_creases.hpp"

#include <isopatch/error.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "api/crease_meshing.hpp"
#include "api/facet_polygons.hpp"
#include "csg/cut_by_planes.hpp"
#include "projection/convex_meshing.hpp"

namespace isopatch {

namespace {

/// The meshing box of `settings` for `surface`.
Box meshing_box(const Surface& surface, const Settings& settings) {
  if (settings.box) return *settings.box;
  return convex_meshing_box(surface, settings).value_or(surface.box());
}

/// p put on plane h exactly where the plane is axis-aligned, else by one projection.
void put_on_plane(Vec3& p, const HalfSpace& h) {
  const Vec3 n(h.a, h.b, h.c);
  for (int axis = 0; axis < 3; ++axis)
    if (n[axis] != 0.0 && n[(axis + 1) % 3] == 0.0 && n[(axis + 2) % 3] == 0.0) {
      p[axis] = -h.d / n[axis];
      return;
    }
  p -= (n.dot(p) + h.d) / n.squaredNorm() * n;
}

}  // namespace

ConvexRegion cutting_planes(const Surface& surface, const Settings& settings, bool by_box) {
  ConvexRegion planes = settings.region;
  if (!by_box) return planes;
  const ConvexRegion sides = box_planes(meshing_box(surface, settings));
  planes.insert(planes.end(), sides.begin(), sides.end());
  return planes;
}

CreasedMesh mesh_clipped_along_creases(const Surface& surface, const ConvexRegion& planes,
                                       const Settings& settings, MeshStats* stats) {
  if (surface.expression() == nullptr || planes.size() > kMostCuttingPlanes) return {};
  const Box box = meshing_box(surface, settings);
  const double edge = default_edge_length(settings, box);
  // Unit normals, so that a plane's value is a distance (the crease analysis reads distances).
  ConvexRegion unit;
  for (const HalfSpace& h : planes) {
    const double length = std::sqrt(h.a * h.a + h.b * h.b + h.c * h.c);
    if (!(length > 0.0)) continue;
    unit.push_back({h.a / length, h.b / length, h.c / length, h.d / length});
  }
  Settings s = settings;
  s.region.clear();
  s.frame.reset();
  s.box = box;
  if (unit.empty()) return mesh_along_creases(surface, s, stats);  // a frame alone
  // In a box grown by two edges, so that its faces cut nothing.
  const Box grown{box.lo - Vec3::Constant(2.0 * edge), box.hi + Vec3::Constant(2.0 * edge)};
  const SurfacePtr cut = cut_by_planes(surface, unit, grown);
  s.box = grown;
  if (!s.size_field && !s.max_error) s.edge_length = edge;
  CreasedMesh creased = mesh_along_creases(*cut, s, stats);
  if (!creased.mesh) return creased;
  Mesh& mesh = *creased.mesh;
  // Triangles on a cutting plane are the cut's caps: taken away.
  const double on = 1e-9 * grown.diagonal();
  std::vector<std::uint64_t> planes_at(mesh.positions.size(), 0);  // bit j: on plane j
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    for (std::size_t j = 0; j < unit.size(); ++j)
      if (std::abs(plane_value(unit[j], mesh.positions[v])) <= on) planes_at[v] |= std::uint64_t{1} << j;
  std::vector<Triangle> kept;
  kept.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
    if ((planes_at[t[0]] & planes_at[t[1]] & planes_at[t[2]]) == 0) kept.push_back(t);
  if (kept.empty())
    throw NoSurfaceError("no surface inside the region and the box: the shape's faces all lie outside them");
  mesh.triangles = std::move(kept);
  // Vertices only the caps used are dropped; those on the cut are put exactly on its planes.
  std::vector<std::uint32_t> id(mesh.positions.size(), UINT32_MAX);
  std::vector<Vec3> positions;
  for (Triangle& t : mesh.triangles)
    for (std::uint32_t& v : t) {
      if (id[v] == UINT32_MAX) {
        id[v] = static_cast<std::uint32_t>(positions.size());
        Vec3 p = mesh.positions[v];
        for (std::size_t j = 0; j < unit.size(); ++j)
          if (planes_at[v] & (std::uint64_t{1} << j)) put_on_plane(p, unit[j]);
        positions.push_back(p);
      }
      v = id[v];
    }
  for (VertexAttribute& a : mesh.attributes) {
    std::vector<float> values(positions.size());
    for (std::size_t v = 0; v < id.size(); ++v)
      if (id[v] != UINT32_MAX) values[id[v]] = a.values[v];
    a.values = std::move(values);
  }
  mesh.positions = std::move(positions);
  if (stats) {
    stats->vertices = mesh.positions.size();
    stats->triangles = mesh.triangles.size();
    if (stats->creases) stats->creases->cut_planes = unit.size();
  }
  return creased;
}

}  // namespace isopatch
