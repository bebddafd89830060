// Meshing in a rotated frame (frame_meshing.hpp).
#include "api/frame_meshing.hpp"

#include <isopatch/error.hpp>

#include "surface/rotated_surface.hpp"

namespace isopatch {
namespace {

ConvexRegion rotated(const ConvexRegion& region, const Mat3& r) {
  ConvexRegion out;
  for (const HalfSpace& h : region) {
    const Vec3 n = r.transpose() * Vec3(h.a, h.b, h.c);
    out.push_back(HalfSpace{n.x(), n.y(), n.z(), h.d});
  }
  return out;
}

bool leaves_box(const Mesh& mesh, const Box& box) {
  const double margin = 1e-9 * box.diagonal();
  for (const Vec3& p : mesh.positions)
    if (!box.contains(p, margin)) return true;
  return false;
}

}  // namespace

Mesh mesh_in_frame(const Surface& surface, const Settings& settings, MeshStats* stats, const Mesher& mesher) {
  if (!settings.frame) throw Error(ErrorKind::Internal, "mesh_in_frame without a frame");
  const Mat3 r = settings.frame->rotation();
  const Box user = valid_box(settings.box.value_or(surface.box()));
  Settings s = settings;
  s.frame.reset();
  // Sizes come from the user's box, not from the larger frame box that holds it.
  s.edge_length = default_edge_length(settings, user);
  s.region = rotated(settings.region, r);
  s.cells.clear();
  for (const ConvexRegion& c : settings.cells) s.cells.push_back(rotated(c, r));
  s.box = frame_bounds(user, r);
  for (Vec3& p : s.refine_around) p = r.transpose() * p;
  const RotatedSurface framed(surface, r, frame_bounds(surface.box(), r));
  Mesh mesh = mesher(framed, s, stats);
  if (settings.cells.empty()) {
    Mesh back = mesh;
    for (Vec3& p : back.positions) p = r * p;
    if (!leaves_box(back, user)) return back;
    // The frame's box holds the user's box: the user's box's planes join the region.
    const ConvexRegion planes = rotated(box_planes(user), r);
    s.region.insert(s.region.end(), planes.begin(), planes.end());
    mesh = mesher(framed, s, stats);
  }
  for (Vec3& p : mesh.positions) p = r * p;
  return mesh;
}

}  // namespace isopatch
