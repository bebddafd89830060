// Splits of long edges of a cut (cut_edge_splits.hpp).
#include "remesh/cut_edge_splits.hpp"

#include <algorithm>
#include <tuple>
#include <vector>

#include "remesh/box_boundary.hpp"
#include "remesh/edge_edits.hpp"
#include "surface/project_point.hpp"

namespace isopatch::cleanup {

namespace {

/// A triangle along a cut whose third vertex lies within this share of the cut edge's length of one end
/// is a sliver: that vertex is merged into the end before the edge is split.
constexpr double kSliverShare = 0.1;

/// The one cut (box face or region plane) both p and q lie on; axis >= 0 for a box face, plane >= 0 for
/// a region plane; neither when they share none or more than one.
struct SharedCut {
  int axis = -1;
  int plane = -1;
};

SharedCut shared_cut(const RemeshRun& run, const Vec3& p, const Vec3& q) {
  SharedCut out;
  int count = 0;
  if (run.settings.box) {
    const Box& box = *run.settings.box;
    for (int k = 0; k < 3; ++k)
      for (const double level : {box.lo[k], box.hi[k]})
        if (p[k] == level && q[k] == level) {
          out.axis = k;
          ++count;
        }
  }
  for (std::size_t k = 0; k < run.planes.size(); ++k)
    if (on_cut_plane(run.planes, static_cast<int>(k), p, run.plane_margin()) &&
        on_cut_plane(run.planes, static_cast<int>(k), q, run.plane_margin())) {
      out.plane = static_cast<int>(k);
      ++count;
    }
  return count == 1 ? out : SharedCut{};
}

/// Whether p lies on a box face other than those across `axis`, or within the margin of a region plane
/// other than `plane`.
bool on_another_cut(const RemeshRun& run, const Vec3& p, int axis, int plane) {
  if (run.settings.box)
    for (int k = 0; k < 3; ++k)
      if (k != axis && (p[k] == run.settings.box->lo[k] || p[k] == run.settings.box->hi[k])) return true;
  for (std::size_t k = 0; k < run.planes.size(); ++k)
    if (static_cast<int>(k) != plane && on_cut_plane(run.planes, static_cast<int>(k), p, run.plane_margin()))
      return true;
  return false;
}

}  // namespace

bool try_split_cut_edge(RemeshRun& run, std::uint32_t a, std::uint32_t b, int merges) {
  if (run.settings.hold_cut) return false;
  const auto e = run.mesh.boundary_edge(a, b);
  if (!e) return false;
  const Vec3 pa = run.mesh.positions[a], pb = run.mesh.positions[b];
  const SharedCut cut = shared_cut(run, pa, pb);
  if (cut.axis < 0 && cut.plane < 0) return false;
  const double length = run.length(a, b);
  Vec3 q = 0.5 * (pa + pb);
  Vec3 gradient;
  if (cut.axis >= 0) {
    q[cut.axis] = pa[cut.axis];
    if (!project_to_surface_in_plane(run.f, q, cut.axis, run.tolerance, length, &gradient)) return false;
  } else if (!project_onto_cut_plane(run.f, q, run.planes, static_cast<std::size_t>(cut.plane), run.tolerance,
                                     run.plane_margin(), length, &gradient)) {
    return false;
  }
  if (!run.in_box(q) || on_another_cut(run, q, cut.axis, cut.plane)) return false;
  // A point of the curve between a and b, not of another piece of the cut nearby.
  if (!((q - pa).norm() < length && (q - pb).norm() < length)) return false;
  const Vec3 n = gradient.normalized();
  if (!run.triangle_ok_with(e->t, b, q, n) || !run.triangle_ok_with(e->t, a, q, n)) {
    // A sliver along the cut (its third vertex beside an end, a cell's crossing point where the cut curve
    // turns): that vertex merged into the end first, then the split tried once more.
    const std::uint32_t c = e->c;
    const std::uint32_t end = run.length(c, a) <= run.length(c, b) ? a : b;
    if (merges > 0 && !run.mesh.locked[c] && run.length(c, end) < kSliverShare * length &&
        try_collapse(run, c, end, kSplitFactor * length)) {
      ++run.stats.collapses;
      return try_split_cut_edge(run, a, b, merges - 1);
    }
    return false;
  }
  const std::uint32_t m = run.mesh.split_boundary(*e, q, n);
  const std::size_t slots = run.mesh.vertex_slots();
  if (cut.axis >= 0) {
    run.slide_axes.resize(slots, -1);
    run.slide_axes[m] = cut.axis;
  } else {
    run.slide_planes.resize(slots, -1);
    run.slide_planes[m] = cut.plane;
  }
  return true;
}

std::size_t split_long_cut_edges(RemeshRun& run) {
  if (run.settings.hold_cut || !run.settings.cleanup.split_cut || (!run.settings.box && run.planes.empty()))
    return 0;
  run.check_cancel();
  // Against the target edge, not the graded sizes: where sizes shrink at a cut feature the mesher's cells
  // shrink too, and the caps that close a cut (api/planar_caps.hpp) are meshed at the target edge.
  const double longest = kSplitFactor * run.settings.sizes.largest;
  std::vector<std::tuple<double, std::uint32_t, std::uint32_t>> long_edges;  // (-length, a, b)
  const auto slots = static_cast<std::uint32_t>(run.mesh.vertex_slots());
  for (std::uint32_t a = 0; a < slots; ++a) {
    if (!run.mesh.locked[a] || !run.mesh.alive(a)) continue;
    for (const std::uint32_t b : run.mesh.boundary_neighbours(a)) {
      const double length = run.length(a, b);
      if (b > a && length > longest) long_edges.emplace_back(-length, a, b);
    }
  }
  std::sort(long_edges.begin(), long_edges.end());
  std::size_t splits = 0;
  for (const auto& [minus_length, a, b] : long_edges)
    if (try_split_cut_edge(run, a, b)) ++splits;
  run.stats.splits += splits;
  return splits;
}

}  // namespace isopatch::cleanup
