// Two smooth solids intersected, meshed as two trimmed faces joined along their crease (curved_cut.hpp).
#include "api/curved_cut.hpp"

#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/self_intersection.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "api/crease_loops.hpp"
#include "api/crease_meshing.hpp"
#include "api/task_arena_run.hpp"
#include "api/zipped_face.hpp"
#include "csg/capped_shape.hpp"

namespace isopatch {

namespace {

/// Crease points lie on both surfaces to this share of the box's diagonal.
constexpr double kOnCrease = 1e-11;
/// The lattice is meshed in the cutter's box (grown) only when that box holds less than this share of
/// the given one.
constexpr double kTrimmedShare = 0.4;

/// One operand meshed whole in `box` as a smooth surface; `trimmed`: its cut by the box is thrown away
/// (no sizes graded there).
Mesh mesh_operand(const Surface& operand, const Settings& settings, const Box& box, double edge,
                  MeshStats* stats, bool trimmed = false) {
  Settings plain = settings;
  plain.cut_sizes = settings.cut_sizes && !trimmed;
  plain.box = box;
  plain.edge_length = settings.edge_length.value_or(edge);
  plain.creases = Creases::Off;
  return mesh_surface(operand, plain, stats);
}

/// zip_face_to_creases(); where its join fails (creases closer than the trim's band), the operand meshed
/// again at half the edge in `mesh_box` (the box `mesh` was made in), joined there, and the whole face
/// cleaned up to the edge: twice the vertices across a strip or neck between creases.
Mesh zip_face(const Mesh& mesh, const Surface& s, const Surface& o, const std::vector<CreaseLoop>& loops,
              bool reversed, double edge, const Settings& settings, const Box& box, const Box& mesh_box) {
  try {
    return zip_face_to_creases(mesh, s, o, loops, reversed, edge, settings, box);
  } catch (const CreaseError&) {
    Settings finer = settings;
    finer.edge_length = 0.5 * edge;
    const Mesh fine = mesh_operand(s, finer, mesh_box, 0.5 * edge, nullptr, true);
    return zip_face_to_creases(fine, s, o, loops, reversed, edge, settings, box, true);
  }
}

/// The triangles of `mesh` within `rings` rings of its first `count` vertices (the crease's).
Mesh near_crease(const Mesh& mesh, std::size_t count, int rings) {
  std::vector<std::uint8_t> near(mesh.positions.size(), 0);
  std::fill(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(count), 1);
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<std::uint8_t> next(near);
    for (const Triangle& t : mesh.triangles)
      if (near[t[0]] || near[t[1]] || near[t[2]]) next[t[0]] = next[t[1]] = next[t[2]] = 1;
    near.swap(next);
  }
  Mesh part;
  part.positions = mesh.positions;
  for (const Triangle& t : mesh.triangles)
    if (near[t[0]] && near[t[1]] && near[t[2]]) part.triangles.push_back(t);
  return part;
}

/// Whether the mesh is closed (its solid inside the box it was meshed in).
bool closed_mesh(const Mesh& mesh) {
  return !mesh.triangles.empty() && analyze_topology(mesh).boundary_edges == 0;
}

}  // namespace

std::optional<Mesh> mesh_curved_cut(const Surface& surface, const Settings& settings, MeshStats* stats) {
  if (settings.creases == Creases::Off || settings.method != Method::Projection || !settings.cells.empty() ||
      !settings.region.empty() || !surface.expression())
    return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  const Box box = settings.box.value_or(surface.box());
  std::optional<CutShape> shape = split_cut_shape(surface, box);
  if (!shape) return std::nullopt;
  Settings plain = settings;
  plain.box = box;
  plain.frame.reset();
  if (analyse_creases(*shape->first, plain) || analyse_creases(*shape->second, plain)) return std::nullopt;
  const double edge = default_edge_length(settings, box);
  // The cutter: the operand whose solid lies in the box (the second first, as formulas write it).
  MeshStats cutter_stats;
  SurfacePtr lattice = shape->first, cutter = shape->second;
  Mesh cutter_mesh = mesh_operand(*cutter, settings, box, edge, &cutter_stats);
  if (!closed_mesh(cutter_mesh)) {
    std::swap(lattice, cutter);
    cutter_stats = MeshStats{};
    cutter_mesh = mesh_operand(*cutter, settings, box, edge, &cutter_stats);
    if (!closed_mesh(cutter_mesh)) return std::nullopt;
  }
  const double analysis = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The lattice only where the cutter's solid is, and a little beyond it, when that saves much; else in
  // the given box, whose cut the multiresolution refinement is known to take as well as the open
  // lattice's (a box of another size can cut it in features that send it back to one level).
  const Box around = bounding_box(cutter_mesh);
  Box lattice_box{(around.lo - Vec3::Constant(3.0 * edge)).cwiseMax(box.lo),
                  (around.hi + Vec3::Constant(3.0 * edge)).cwiseMin(box.hi)};
  if (lattice_box.size().prod() > kTrimmedShare * box.size().prod()) lattice_box = box;
  Mesh lattice_mesh = mesh_operand(*lattice, settings, lattice_box, edge, stats, true);
  const auto join_start = std::chrono::steady_clock::now();
  const double tolerance = kOnCrease * box.diagonal();
  Mesh mesh;
  std::size_t crease_vertices = 0, loops_count = 0;
  AngleRepair repair;
  run_in_task_arena(settings, stats, [&] {
    const std::vector<CreaseLoop> loops =
        trace_crease_loops(lattice_mesh, *lattice, *cutter, edge, tolerance);
    loops_count = loops.size();
    for (const CreaseLoop& loop : loops) crease_vertices += loop.points.size();
    mesh = zip_face(lattice_mesh, *lattice, *cutter, loops, false, edge, settings, box, lattice_box);
    const Mesh other = zip_face(cutter_mesh, *cutter, *lattice, loops, true, edge, settings, box, box);
    const auto offset = static_cast<std::uint32_t>(mesh.positions.size() - crease_vertices);
    mesh.positions.insert(mesh.positions.end(),
                          other.positions.begin() + static_cast<std::ptrdiff_t>(crease_vertices),
                          other.positions.end());
    for (Triangle t : other.triangles) {
      for (std::uint32_t& v : t)
        if (v >= crease_vertices) v += offset;
      mesh.triangles.push_back(t);
    }
    repair = repair_crease_angles(mesh, {lattice, cutter}, box);
    return 0;
  });
  const TopologyReport topology = analyze_topology(mesh);
  if (!topology.watertight() || !topology.manifold() || !topology.consistently_oriented())
    throw CreaseError("the two solids' mesh is not a closed 2-manifold (" +
                      std::to_string(topology.boundary_edges) + " boundary edges, " +
                      std::to_string(topology.non_manifold_edges + topology.non_manifold_vertices) +
                      " non-manifold places): a feature narrower than an edge at the crease; a smaller "
                      "--edge-length, or --creases off for a smooth mesh");
  // The joins are new: no triangle near the crease may cross another (a crease loop zipped to the wrong
  // boundary, two creases closer than an edge).
  const SelfIntersectionReport crossing = find_self_intersections(near_crease(mesh, crease_vertices, 4), 1);
  if (crossing.pairs > 0) {
    const Vec3& p = crossing.example_point;
    throw CreaseError("the two solids' faces cross near their crease at (" + std::to_string(p.x()) + ", " +
                      std::to_string(p.y()) + ", " + std::to_string(p.z()) +
                      "): creases closer than an edge; a smaller --edge-length, or --creases off");
  }
  const double joining = std::chrono::duration<double>(std::chrono::steady_clock::now() - join_start).count();
  if (stats) {
    CreaseStats c;
    c.faces = 2;
    c.pieces = 2;
    c.creases = loops_count;
    c.crease_vertices = crease_vertices;
    c.repair_moves = repair.moved;
    c.seconds = analysis + joining;
    stats->creases = c;
    stats->seconds += c.seconds + cutter_stats.seconds;
    stats->value_evaluations += cutter_stats.value_evaluations;
    stats->gradient_evaluations += cutter_stats.gradient_evaluations;
    stats->times.add("creases", analysis);
    stats->times.add("caps", joining);
    stats->vertices = mesh.vertex_count();
    stats->triangles = mesh.triangle_count();
  }
  return mesh;
}

}  // namespace isopatch
