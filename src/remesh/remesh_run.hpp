// The state of one surface-bound clean-up run (remesh_on_surface): the mesh, the surface, the sizes, the
// statistics, the settings and the geometric checks every pass shares. The passes (edge_edits.hpp,
// cleanup_flips.hpp, relaxation.hpp, small_angle_repair.hpp, error_bound.hpp) are free functions on it.
#pragma once

#include <isopatch/error.hpp>
#include <isopatch/remesh.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <type_traits>
#include <vector>

#include "core/stage_timer.hpp"
#include "core/triangle_angle.hpp"
#include "remesh/box_boundary.hpp"
#include "remesh/editable_mesh.hpp"
#include "remesh/remesh_presets.hpp"
#include "remesh/remesh_thresholds.hpp"
#include "remesh/size_field.hpp"
#include "remesh/slot_renumbering.hpp"
#include "surface/project_point.hpp"
#include "surface/sampler.hpp"

namespace isopatch::cleanup {

using namespace remesh_thresholds;

/// One clean-up run: `mesh` is edited in place on the surface f = 0 of `surface`, with the sizes of
/// `settings`; `tolerance` is the projection's tolerance. The references must outlive the run.
class RemeshRun {
 public:
  RemeshRun(const Surface& surface, EditableMesh& editable, const RemeshSettings& run_settings,
            double projection_tolerance)
      : f(surface),
        mesh(editable),
        settings(run_settings),
        effort(cleanup_effort(run_settings.cleanup)),
        sizes(surface, run_settings),
        tolerance(projection_tolerance) {}

  /// Drops the mesh's dead slots (EditableMesh::compact, or with space_order
  /// EditableMesh::compact_in_space_order) and renumbers the per-vertex data held here.
  void compact(bool space_order = false) {
    const std::vector<std::uint32_t> new_id = space_order ? mesh.compact_in_space_order() : mesh.compact();
    sizes.renumber(new_id);
    // New slots (from splits) were never in these lists: they stay -1.
    renumber_slots(slide_axes, new_id, -1);
    renumber_slots(slide_planes, new_id, -1);
  }

  /// Runs `pass`, adding its wall time to stage `name` of the statistics; returns what it returns.
  template <class Pass>
  std::invoke_result_t<Pass> timed(const char* name, Pass pass) {
    const StageTimer timer(&stats.times, name);
    return pass();
  }

  /// Reports `done` of `total` clean-up steps through settings.progress (stage "cleanup").
  void report(std::size_t done, std::size_t total) const {
    if (settings.progress) settings.progress(Progress{done, total, "cleanup"});
  }

  /// Throws LimitError("cancelled") once settings.cancel is set.
  void check_cancel() const {
    if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) throw LimitError("cancelled");
  }

  /// Whether p lies in the box and inside the region's planes (to within plane_margin()).
  bool in_box(const Vec3& p) const {
    for (const CutPlane& plane : planes)
      if (plane.distance(p) > plane_margin()) return false;
    if (!settings.box) return true;
    return (p.array() >= settings.box->lo.array()).all() && (p.array() <= settings.box->hi.array()).all();
  }
  double plane_margin() const { return kCutPlaneTolerance * settings.sizes.largest; }

  /// p moved onto f = 0 (steps at most max_step), with its unit normal; false on failure or outside the box.
  bool project(Vec3& p, Vec3& normal, double max_step) const {
    Vec3 gradient;
    if (!project_to_surface(f, p, tolerance, max_step, &gradient)) return false;
    if (!in_box(p)) return false;
    normal = gradient.normalized();
    return true;
  }

  /// Whether the triangle p0 p1 p2 is not degenerate and its normal is within kMinNormalDot of the
  /// vertex normals n0, n1, n2 (it does not fold against the surface).
  bool triangle_ok(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& n0, const Vec3& n1,
                   const Vec3& n2) const {
    const Vec3 cross = (p1 - p0).cross(p2 - p0);
    const double norm = cross.norm();
    const double scale =
        std::max({(p1 - p0).squaredNorm(), (p2 - p1).squaredNorm(), (p0 - p2).squaredNorm()});
    if (!(norm > 1e-12 * scale)) return false;
    const Vec3 n = cross / norm;
    return n.dot(n0) >= kMinNormalDot && n.dot(n1) >= kMinNormalDot && n.dot(n2) >= kMinNormalDot;
  }

  /// Triangle t with vertex `from` at position p and normal n (and others as they are).
  bool triangle_ok_with(std::uint32_t t, std::uint32_t from, const Vec3& p, const Vec3& n) const {
    Vec3 q[3], m[3];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = mesh.triangles[t][static_cast<std::size_t>(i)];
      q[i] = v == from ? p : mesh.positions[v];
      m[i] = v == from ? n : mesh.normals[v];
    }
    return triangle_ok(q[0], q[1], q[2], m[0], m[1], m[2]);
  }

  /// triangle_ok on triangle t of the mesh as it is.
  bool triangle_ok(const Triangle& t) const {
    return triangle_ok(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]], mesh.normals[t[0]],
                       mesh.normals[t[1]], mesh.normals[t[2]]);
  }

  /// The length of the edge between vertices a and b.
  double length(std::uint32_t a, std::uint32_t b) const {
    return (mesh.positions[a] - mesh.positions[b]).norm();
  }

  /// The ratio of an edge's length to its size below which it is collapsed (with the error bound, in a
  /// local run, or else).
  double collapse_factor() const {
    if (settings.sizes.max_error) return kErrorCollapseFactor;
    return effort.local_only ? kLocalCollapseFactor : kCollapseFactor;
  }

  /// The axis of the box face along which boundary vertex v may slide, or -1 (box_boundary.hpp).
  int slide_axis(std::uint32_t v) const { return v < slide_axes.size() ? slide_axes[v] : -1; }
  /// The region plane along which boundary vertex v may slide, or -1 (box_boundary.hpp).
  int slide_plane(std::uint32_t v) const { return v < slide_planes.size() ? slide_planes[v] : -1; }
  /// Sets planes, slide_axes and slide_planes from the settings' box and region planes (box_boundary.hpp);
  /// runs first, before any pass reads slide_axis or slide_plane.
  void find_sliding_vertices() {
    planes = cut_planes(settings.cut_planes);
    if (settings.hold_cut) return;  // no vertex slides: slide_axis and slide_plane are -1 everywhere
    if (settings.box) slide_axes = sliding_axes(mesh, *settings.box, planes, plane_margin());
    slide_planes = sliding_planes(mesh, planes, settings.box ? &*settings.box : nullptr, plane_margin());
  }

  /// The fewest neighbours v may keep after a flip or collapse takes one: 3, but 2 (one triangle) at a
  /// corner of the cut (on two faces or planes, never moved), whose wedge may be too narrow for two good
  /// triangles. A sliding cut vertex keeps two: with one, its corners would lie on one nearly straight cut.
  unsigned fewest(std::uint32_t v) const {
    return mesh.locked[v] && slide_axis(v) < 0 && slide_plane(v) < 0 ? 2u : 3u;
  }

  /// The cosine of the smallest angle of triangle t of the mesh (triangle_angle.hpp).
  double smallest_angle_cosine(const Triangle& t) const {
    return isopatch::smallest_angle_cosine(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
  }

  const double cos_glide = std::cos(kGlideAngle * std::numbers::pi / 180.0);
  const double cos_repair = std::cos(kRepairAngle * std::numbers::pi / 180.0);
  const double cos_30 = std::cos(30.0 * std::numbers::pi / 180.0);
  std::vector<int> slide_axes;    ///< per vertex slot at the start; empty without a box
  std::vector<int> slide_planes;  ///< per vertex slot at the start; -1 off the region's planes
  std::vector<CutPlane> planes;   ///< the region's planes (unit normals), set by find_sliding_vertices
  std::vector<std::uint32_t> near_defects;  ///< a local run's vertices near its defects, relaxed alone
  Sampler f;
  EditableMesh& mesh;
  const RemeshSettings& settings;
  const CleanupEffort effort;  ///< what settings.cleanup asks for, its preset applied
  SizeField sizes;
  double tolerance;
  RemeshStats stats;
};

}  // namespace isopatch::cleanup
