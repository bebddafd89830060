// Two smooth solids capped by axis-aligned planes (capped_curved_cut.hpp).
#include "api/capped_curved_cut.hpp"

#include <isopatch/error.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "api/crease_meshing.hpp"
#include "api/curved_cut.hpp"
#include "api/cut_and_caps.hpp"
#include "api/planar_caps.hpp"
#include "api/task_arena_run.hpp"
#include "csg/capped_shape.hpp"
#include "csg/face_set.hpp"

namespace isopatch {

namespace {

/// max(a, b), or -max(a, b) when `negated` (the union of two solids as CutShape reads it), as a surface:
/// the solid the caps close (their sides are sampled inside it).
class SolidOfTwo final : public Surface {
 public:
  SolidOfTwo(SurfacePtr a, SurfacePtr b, bool negated)
      : Surface(negated ? "min(a, b)" : "max(a, b)", a->box()),
        a_(std::move(a)),
        b_(std::move(b)),
        sign_(negated ? -1.0 : 1.0) {}
  double value(const Vec3& p) const override { return sign_ * std::max(a_->value(p), b_->value(p)); }
  ValueGradient value_gradient(const Vec3& p) const override {
    const ValueGradient a = a_->value_gradient(p), b = b_->value_gradient(p);
    const ValueGradient& larger = a.value >= b.value ? a : b;
    return ValueGradient{sign_ * larger.value, sign_ * larger.gradient};
  }
  SecondOrder second_order(const Vec3& p) const override {
    SecondOrder s = a_->value(p) >= b_->value(p) ? a_->second_order(p) : b_->second_order(p);
    s.value *= sign_;
    s.gradient *= sign_;
    s.hessian *= sign_;
    return s;
  }

 private:
  SurfacePtr a_, b_;
  double sign_;
};

/// An axis-aligned plane of the part: the axis, the level, and whether the solid lies below it.
struct AxisPlane {
  int axis = 0;
  double level = 0.0;
  bool below = true;
};

/// The planes as axis-aligned ones, or nullopt when one is not perpendicular to an axis.
std::optional<std::vector<AxisPlane>> axis_planes(const ConvexRegion& planes) {
  std::vector<AxisPlane> out;
  for (const HalfSpace& h : planes) {
    const Vec3 n(h.a, h.b, h.c);
    int axis = -1;
    for (int k = 0; k < 3; ++k)
      if (std::abs(n[k]) == 1.0 && n[(k + 1) % 3] == 0.0 && n[(k + 2) % 3] == 0.0) axis = k;
    if (axis < 0) return std::nullopt;
    // n_k x_k + d <= 0: x_k <= -d (n_k = 1) or x_k >= d (n_k = -1).
    out.push_back(n[axis] > 0.0 ? AxisPlane{axis, -h.d, true} : AxisPlane{axis, h.d, false});
  }
  return out;
}

}  // namespace

std::optional<Mesh> mesh_capped_curved_cut(const Surface& surface, const Settings& settings,
                                           MeshStats* stats) {
  if (settings.creases == Creases::Off || settings.method != Method::Projection || !settings.cells.empty() ||
      !settings.region.empty() || !surface.expression())
    return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  const Box box = settings.box.value_or(surface.box());
  std::optional<CappedCutShape> shape = split_capped_cut_shape(surface, box);
  if (!shape) return std::nullopt;
  const std::optional<std::vector<AxisPlane>> planes = axis_planes(shape->planes);
  if (!planes) return std::nullopt;
  // The planes' box inside the given one; the planes that bound it inside the box (or on its faces) are
  // the part's, capped; the others lie beyond the box and change nothing.
  const double on_plane = kCapOnPlane * box.diagonal();
  const double edge = default_edge_length(settings, box);
  Box inner = box, caps_box = box;
  ConvexRegion capped;
  for (std::size_t i = 0; i < planes->size(); ++i) {
    const AxisPlane& p = (*planes)[i];
    double& side = p.below ? inner.hi[p.axis] : inner.lo[p.axis];
    const bool cuts = p.below ? p.level < box.hi[p.axis] + on_plane : p.level > box.lo[p.axis] - on_plane;
    if (!cuts) continue;
    side = p.below ? std::min(side, p.level) : std::max(side, p.level);
    capped.push_back(shape->planes[i]);
    // A plane on a face of the box: the box grown there, so that its face cuts nothing.
    if (std::abs(p.level - (p.below ? box.hi[p.axis] : box.lo[p.axis])) <= on_plane) {
      if (p.below)
        caps_box.hi[p.axis] = box.hi[p.axis] + 2.0 * edge;
      else
        caps_box.lo[p.axis] = box.lo[p.axis] - 2.0 * edge;
    }
  }
  for (int k = 0; k < 3; ++k)
    if (!(inner.hi[k] - inner.lo[k] > 2.0 * edge)) return std::nullopt;
  Settings part = settings;
  part.box = inner;
  part.edge_length = edge;
  const double analysis = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The planes' box may hold no surface of an operand (the part is then the other's, or empty): not this
  // form, the paths after it decide.
  std::optional<Mesh> mesh;
  try {
    mesh = mesh_two_solids(shape->solids, part, stats);
  } catch (const NoSurfaceError&) {
    return std::nullopt;
  }
  if (!mesh) return std::nullopt;
  const auto caps_start = std::chrono::steady_clock::now();
  const auto solid =
      std::make_shared<const SolidOfTwo>(shape->solids.first, shape->solids.second, shape->solids.united);
  std::vector<SurfacePtr> faces{shape->solids.first, shape->solids.second};
  for (const HalfSpace& h : capped) faces.push_back(plane_surface(Vec3(h.a, h.b, h.c), -h.d, box));
  AngleRepair repair;
  const CapReport caps = run_in_task_arena(settings, stats, [&] {
    CapReport added =
        close_with_caps(*mesh, solid.get(), capped, capped.size(), caps_box, edge, on_plane, settings, false);
    // The last repair of small angles over the whole part; vertices on the box's faces stay there.
    std::vector<std::uint8_t> held(mesh->vertex_count(), 0);
    for (std::size_t v = 0; v < held.size(); ++v)
      held[v] = caps_box.contains(mesh->positions[v], -on_plane) ? 0 : 1;
    repair = repair_crease_angles(*mesh, faces, box, &held);
    return added;
  });
  const TopologyReport topology = analyze_topology(*mesh);
  if (topology.boundary_edges != caps.open_edges + caps.open_cap_edges || !topology.manifold() ||
      !topology.consistently_oriented()) {
    throw CreaseError("the capped part of two solids is not a closed 2-manifold (" +
                      std::to_string(topology.boundary_edges) + " boundary edges where the box cuts " +
                      std::to_string(caps.open_edges + caps.open_cap_edges) +
                      "): a cap plane tangent to a surface or a feature narrower than an edge; a smaller "
                      "--edge-length, or --creases off for a smooth mesh");
  }
  const double capping = std::chrono::duration<double>(std::chrono::steady_clock::now() - caps_start).count();
  if (stats && stats->creases) {
    CreaseStats& c = *stats->creases;
    c.faces += caps.caps;
    c.pieces += caps.caps;
    c.caps = caps.caps;
    c.crease_vertices += caps.crease_vertices;
    c.repair_moves += repair.moved;
    c.seconds += analysis + capping;
    stats->seconds += analysis + capping;
    stats->times.add("creases", analysis);
    stats->times.add("caps", capping);
    stats->vertices = mesh->vertex_count();
    stats->triangles = mesh->triangle_count();
  }
  return mesh;
}

}  // namespace isopatch
