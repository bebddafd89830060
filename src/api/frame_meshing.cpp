// Meshing in a rotated frame (frame_meshing.hpp).
#include "api/frame_meshing.hpp"

#include <isopatch/error.hpp>

#include <chrono>

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

/// Whether f = 0 meets the faces of `box` for certain: f takes both signs (or 0) among 33 x 33 samples
/// of each face, whose union is connected. False says nothing.
bool meets_box_faces(const Surface& f, const Box& box) {
  constexpr int kSamples = 33;
  bool negative = false, positive = false;
  for (int axis = 0; axis < 3; ++axis)
    for (const double level : {box.lo[axis], box.hi[axis]}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int i = 0; i < kSamples; ++i)
        for (int j = 0; j < kSamples; ++j) {
          Vec3 p;
          p[axis] = level;
          p[u] = box.lo[u] + box.size()[u] * i / (kSamples - 1);
          p[v] = box.lo[v] + box.size()[v] * j / (kSamples - 1);
          const double value = f.value(p);
          negative = negative || value <= 0.0;
          positive = positive || value >= 0.0;
          if (negative && positive) return true;
        }
    }
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
  // The frame's box holds the user's box: where f = 0 crosses the user's box, its planes join the
  // region. Known from samples on its faces, that is decided before meshing; else a first mesh in the
  // frame's box says it (its time kept as the stage "frame_trial" when it is made again).
  const auto with_box_planes = [&] {
    const ConvexRegion planes = rotated(box_planes(user), r);
    s.region.insert(s.region.end(), planes.begin(), planes.end());
  };
  const bool cut_by_box = settings.cells.empty() && meets_box_faces(surface, user);
  if (cut_by_box) with_box_planes();
  const auto start = std::chrono::steady_clock::now();
  Mesh mesh = mesher(framed, s, stats);
  if (settings.cells.empty() && !cut_by_box) {
    Mesh back = mesh;
    for (Vec3& p : back.positions) p = r * p;
    if (!leaves_box(back, user)) return back;
    const double trial = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    with_box_planes();
    mesh = mesher(framed, s, stats);
    if (stats) {
      stats->times.add("frame_trial", trial);
      stats->seconds += trial;
    }
  }
  for (Vec3& p : mesh.positions) p = r * p;
  return mesh;
}

}  // namespace isopatch
