// A smooth solid capped by a convex polyhedron, meshed as a cut surface and its caps
// (capped_meshing.hpp).
#include "api/capped_meshing.hpp"

#include <isopatch/isopatch.hpp>

#include <chrono>
#include <utility>

#include "api/crease_meshing.hpp"
#include "api/cut_and_caps.hpp"
#include "csg/capped_shape.hpp"
#include "projection/convex_meshing.hpp"

namespace isopatch {

std::optional<Mesh> mesh_capped_shape(const Surface& surface, const Settings& settings, MeshStats* stats) {
  if (settings.creases == Creases::Off || settings.method != Method::Projection || !settings.cells.empty() ||
      !surface.expression())
    return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  // A region decides the box when none is given (as for any surface: convex_meshing.hpp).
  const Box box =
      settings.box ? *settings.box : convex_meshing_box(surface, settings).value_or(surface.box());
  std::optional<CappedShape> shape = split_capped_shape(surface, box);
  if (!shape) return std::nullopt;
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
