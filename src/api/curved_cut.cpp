// Two smooth solids intersected, meshed as two trimmed faces joined along their crease (curved_cut.hpp).
#include "api/curved_cut.hpp"

#include <isopatch/error.hpp>
#include <isopatch/interval.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/self_intersection.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/crease_loops.hpp"
#include "api/crease_meshing.hpp"
#include "api/task_arena_run.hpp"
#include "api/zipped_face.hpp"
#include "core/triangle_angle.hpp"
#include "csg/capped_shape.hpp"
#include "csg/crease_graph.hpp"

namespace isopatch {

namespace {

/// Crease points lie on both surfaces to this share of the box's diagonal.
constexpr double kOnCrease = 1e-11;
/// The lattice is meshed in the cutter's box (grown) only when that box holds less than this share of
/// the given one.
constexpr double kTrimmedShare = 0.4;

/// One operand meshed whole in `box` as a smooth surface; `trimmed`: its cut by the box is thrown away
/// (no sizes graded there); `split_cut`: the clean-up splits the cut's long edges on the cut curve
/// (CleanupSettings::split_cut), else the cut stays as the mesher made it.
Mesh mesh_operand(const Surface& operand, const Settings& settings, const Box& box, double edge,
                  MeshStats* stats, bool trimmed = false, bool split_cut = false) {
  Settings plain = settings;
  plain.cut_sizes = settings.cut_sizes && !trimmed;
  plain.box = box;
  plain.edge_length = settings.edge_length.value_or(edge);
  plain.creases = Creases::Off;
  plain.split_cut = split_cut;
  return mesh_surface(operand, plain, stats);
}

/// zip_face_to_creases(); where its join fails, with `cut` BoxCut::Runs the face's whole ring at the box
/// joined anew, then (creases closer than the trim's band) the operand meshed again at half the edge in
/// `mesh_box` (the box `mesh` was made in), joined there, and the whole face cleaned up to the edge: twice
/// the vertices across a strip or neck between creases. `cut` None: the part is closed, the operand
/// is meshed closed. `fine`: straight to the join at half the edge.
Mesh zip_face(const Mesh& mesh, const Surface& s, const Surface& o, const std::vector<CreaseLoop>& loops,
              bool reversed, double edge, const Settings& settings, const Box& box, const Box& mesh_box,
              BoxCut cut, bool fine) {
  try {
    if (fine) throw CreaseError("the join at half the edge asked for");
    return zip_face_to_creases(mesh, s, o, loops, reversed, edge, settings, box, false, cut);
  } catch (const CreaseError&) {
    // Where the trimmed face's runs to the box do not close, its whole ring at the box joined anew first.
    if (cut == BoxCut::Runs && !fine) {
      try {
        return zip_face_to_creases(mesh, s, o, loops, reversed, edge, settings, box, false, BoxCut::Ring);
      } catch (const CreaseError&) {
      }
    }
    Settings finer = settings;
    finer.edge_length = 0.5 * edge;
    const Mesh half_edge_mesh = mesh_operand(s, finer, mesh_box, 0.5 * edge, nullptr, cut == BoxCut::None);
    return zip_face_to_creases(half_edge_mesh, s, o, loops, reversed, edge, settings, box, true, cut);
  }
}

/// The triangles of `mesh` within `rings` rings of its first `count` vertices (the crease's) and of the
/// vertices `also` flags (when given: the boundary on the box).
Mesh near_crease(const Mesh& mesh, std::size_t count, int rings,
                 const std::vector<std::uint8_t>* also = nullptr) {
  std::vector<std::uint8_t> near(mesh.positions.size(), 0);
  std::fill(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(count), 1);
  if (also)
    for (std::size_t v = 0; v < near.size(); ++v) near[v] = near[v] || (*also)[v];
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

/// Whether `minus` (an operand -a of a union) is negative on every face of `box`, proved by interval bounds
/// over 8 x 8 tiles of each face: a's solid stays off the box's faces. False when a bound is not finite.
bool negative_on_the_box(const Surface& minus, const Box& box) {
  constexpr int kTiles = 8;
  for (int axis = 0; axis < 3; ++axis)
    for (const double level : {box.lo[axis], box.hi[axis]}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int i = 0; i < kTiles; ++i)
        for (int j = 0; j < kTiles; ++j) {
          Box tile;
          tile.lo[axis] = tile.hi[axis] = level;
          tile.lo[u] = box.lo[u] + box.size()[u] * i / kTiles;
          tile.hi[u] = box.lo[u] + box.size()[u] * (i + 1) / kTiles;
          tile.lo[v] = box.lo[v] + box.size()[v] * j / kTiles;
          tile.hi[v] = box.lo[v] + box.size()[v] * (j + 1) / kTiles;
          const std::optional<Interval> b = minus.bound(tile);
          if (!b || !(b->hi < 0.0)) return false;
        }
    }
  return true;
}

/// Whether the mesh is closed and bounds its solid (the solid inside the box it was meshed in): not the
/// closed surface of a complement (-a for a ball a), whose solid reaches the box and whose mesh, oriented
/// along the gradient, encloses a negative volume.
bool closed_mesh(const Mesh& mesh) {
  if (mesh.triangles.empty()) return false;
  const TopologyReport topology = analyze_topology(mesh);
  double volume = 0.0;
  for (const ComponentTopology& c : topology.components) volume += c.volume;
  return topology.boundary_edges == 0 && volume > 0.0;
}

/// Flags the vertices of `mesh` on its boundary edges.
std::vector<std::uint8_t> boundary_vertices(const Mesh& mesh) {
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
    for (std::size_t k = 0; k < 3; ++k) {
      const auto [u, v] = std::minmax(t[k], t[(k + 1) % 3]);
      edges.push_back((static_cast<std::uint64_t>(u) << 32) | v);
    }
  std::sort(edges.begin(), edges.end());
  std::vector<std::uint8_t> on(mesh.positions.size(), 0);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) on[edges[i] >> 32] = on[edges[i] & 0xffffffffu] = 1;
    i = j;
  }
  return on;
}

/// The first boundary vertex of `mesh` (`on`) farther than `tolerance` from every face of `box`, if any.
std::optional<Vec3> off_the_box(const Mesh& mesh, const std::vector<std::uint8_t>& on, const Box& box,
                                double tolerance) {
  for (std::size_t v = 0; v < on.size(); ++v) {
    if (!on[v]) continue;
    const Vec3& p = mesh.positions[v];
    const double gap = std::min((p - box.lo).cwiseAbs().minCoeff(), (p - box.hi).cwiseAbs().minCoeff());
    if (gap > tolerance) return p;
  }
  return std::nullopt;
}

/// What join_faces() puts together.
struct JoinInput {
  const Mesh& lattice_mesh;
  const Mesh& cutter_mesh;
  const SurfacePtr& lattice;
  const SurfacePtr& cutter;
  const std::vector<CreaseLoop>& loops;
  std::size_t crease_vertices;
  double edge;
  const Settings& settings;
  const Box& box;
  const Box& lattice_box;
  bool open;  ///< the box cuts the part: the crease holds arcs, the part's boundary lies on the box
};

/// Both faces trimmed and zipped to the crease (zip_face()), put together sharing the crease's vertices,
/// their crease angles repaired (the boundary on the box held), and checked: a 2-manifold, outward,
/// closed unless the box cuts it (then every boundary vertex on the box), no triangle near the crease or
/// the box crossing another. `rejoin_ring`: each face's whole ring at the box is joined anew. `fine`:
/// both faces joined on their operands' meshes at half the edge (zip_face()).
/// \throw CreaseError naming the place where a check fails; the errors of zip_face().
Mesh join_faces(const JoinInput& in, bool rejoin_ring, AngleRepair& repair, bool fine = false) {
  const std::size_t crease_vertices = in.crease_vertices;
  const BoxCut cut = !in.open ? BoxCut::None : rejoin_ring ? BoxCut::Ring : BoxCut::Runs;
  Mesh mesh = zip_face(in.lattice_mesh, *in.lattice, *in.cutter, in.loops, false, in.edge, in.settings,
                       in.box, in.lattice_box, cut, fine);
  const Mesh other = zip_face(in.cutter_mesh, *in.cutter, *in.lattice, in.loops, true, in.edge, in.settings,
                              in.box, in.box, cut, fine);
  const auto offset = static_cast<std::uint32_t>(mesh.positions.size() - crease_vertices);
  mesh.positions.insert(mesh.positions.end(),
                        other.positions.begin() + static_cast<std::ptrdiff_t>(crease_vertices),
                        other.positions.end());
  for (Triangle t : other.triangles) {
    for (std::uint32_t& v : t)
      if (v >= crease_vertices) v += offset;
    mesh.triangles.push_back(t);
  }
  // Where the box cuts the part, its boundary stays on the box's faces.
  const std::vector<std::uint8_t> on_box = in.open ? boundary_vertices(mesh) : std::vector<std::uint8_t>{};
  repair = repair_crease_angles(mesh, {in.lattice, in.cutter}, in.box, in.open ? &on_box : nullptr);
  const TopologyReport topology = analyze_topology(mesh);
  if (in.open) {
    if (const std::optional<Vec3> p = off_the_box(mesh, on_box, in.box, kOnCrease * in.box.diagonal()))
      throw CreaseError("the two solids' mesh has a boundary off the box near " + point_text(*p) +
                        ": a feature narrower than an edge at the crease; a smaller --edge-length, or "
                        "--creases off for a smooth mesh");
  }
  if ((!in.open && !topology.watertight()) || !topology.manifold() || !topology.consistently_oriented())
    throw CreaseError("the two solids' mesh is not a closed 2-manifold (" +
                      std::to_string(topology.boundary_edges) + " boundary edges, " +
                      std::to_string(topology.non_manifold_edges + topology.non_manifold_vertices) +
                      " non-manifold places): a feature narrower than an edge at the crease; a smaller "
                      "--edge-length, or --creases off for a smooth mesh");
  // The joins are new: no triangle near the crease (or the box, where the faces were joined to it) may
  // cross another (a crease loop zipped to the wrong boundary, two creases closer than an edge).
  const SelfIntersectionReport crossing =
      find_self_intersections(near_crease(mesh, crease_vertices, 4, in.open ? &on_box : nullptr), 1);
  if (crossing.pairs > 0) {
    const Vec3& p = crossing.example_point;
    throw CreaseError("the two solids' faces cross near their crease at (" + std::to_string(p.x()) + ", " +
                      std::to_string(p.y()) + ", " + std::to_string(p.z()) +
                      "): creases closer than an edge; a smaller --edge-length, or --creases off");
  }
  return mesh;
}

}  // namespace

std::optional<Mesh> mesh_curved_cut(const Surface& surface, const Settings& settings, MeshStats* stats) {
  if (settings.creases == Creases::Off || settings.method != Method::Projection || !settings.cells.empty() ||
      !settings.region.empty() || !surface.expression())
    return std::nullopt;
  const Box box = settings.box.value_or(surface.box());
  std::optional<CutShape> shape = split_cut_shape(surface, box);
  if (!shape) return std::nullopt;
  Settings plain = settings;
  plain.box = box;
  return mesh_two_solids(*shape, plain, stats);
}

namespace {

/// A join on split cuts whose smallest angle is under this (degrees: the crease paths' floor) is tried on
/// the mesher's cuts too, and the better kept: never a smaller angle than the mesher's cuts give.
constexpr double kSecondJoinAngle = 25.0;

/// The smallest angle of the mesh's triangles in degrees (180 without one).
double smallest_angle(const Mesh& mesh) {
  double cosine = -1.0;
  for (const Triangle& t : mesh.triangles)
    cosine = std::max(
        cosine, smallest_angle_cosine(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]));
  return std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

/// mesh_two_solids() with the operands' cuts split (`split`) or as the mesher made them. With `split` the
/// join at half the edge is not tried (a join that fails on the split cuts is tried again on the
/// mesher's, by the caller); `*cut_open` tells whether the box cut the part (else `split` changed
/// nothing).
std::optional<Mesh> two_solids(const CutShape& shape, const Settings& settings, MeshStats* stats, bool split,
                               bool* cut_open) {
  const auto start = std::chrono::steady_clock::now();
  *cut_open = false;
  const Box box = *settings.box;
  // A union of two solids inside the box (two balls) has faces the general crease path cuts into discs,
  // with better valences than here: left to it. A union the box cuts (a lattice with a solid in it) is
  // meshed here.
  if (shape.united && negative_on_the_box(*shape.first, box) && negative_on_the_box(*shape.second, box))
    return std::nullopt;
  Settings plain = settings;
  plain.frame.reset();
  // An operand with creases of its own, in the box or leaving it, is not smooth: not this form.
  for (const SurfacePtr& operand : {shape.first, shape.second}) {
    std::optional<Vec3> leaves;
    if (analyse_creases(*operand, plain, &leaves) || leaves) return std::nullopt;
  }
  const double edge = default_edge_length(settings, box);
  // The cutter: the operand whose solid lies in the box (the second first, as formulas write it). When
  // neither does, the box cuts the part open: both operands are meshed in it with their boundary on its
  // faces, and the crease is cut into arcs from the box to the box.
  // An operand that does not cross the box leaves the part to the other alone: not this form.
  MeshStats cutter_stats;
  SurfacePtr lattice = shape.first, cutter = shape.second;
  const auto operand_mesh = [&](const Surface& operand, MeshStats* run) -> std::optional<Mesh> {
    try {
      return mesh_operand(operand, settings, box, edge, run, false, split);
    } catch (const NoSurfaceError&) {
      return std::nullopt;
    }
  };
  std::optional<Mesh> second_mesh = operand_mesh(*cutter, &cutter_stats);
  if (!second_mesh) return std::nullopt;
  Mesh cutter_mesh = std::move(*second_mesh);
  bool open = false;
  std::optional<Mesh> open_lattice;
  if (!closed_mesh(cutter_mesh)) {
    MeshStats first_stats;
    std::optional<Mesh> first = operand_mesh(*lattice, &first_stats);
    if (!first) return std::nullopt;
    Mesh first_mesh = std::move(*first);
    if (closed_mesh(first_mesh)) {
      std::swap(lattice, cutter);
      cutter_mesh = std::move(first_mesh);
      cutter_stats = first_stats;
    } else {
      if (cutter_mesh.triangles.empty() || first_mesh.triangles.empty()) return std::nullopt;
      // Two balls united, one solid of them reaching no face of the box only where the interval bounds
      // could not show it: as below.
      if (shape.united && analyze_topology(cutter_mesh).boundary_edges == 0 &&
          analyze_topology(first_mesh).boundary_edges == 0)
        return std::nullopt;
      open = true;
      *cut_open = true;
      open_lattice = std::move(first_mesh);
      if (stats) *stats = first_stats;
    }
  }
  const double analysis = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The lattice only where the cutter's solid is, and a little beyond it, when that saves much; else in
  // the given box, whose cut the multiresolution refinement is known to take as well as the open
  // lattice's (a box of another size can cut it in features that send it back to one level).
  const Box around = bounding_box(cutter_mesh);
  Box lattice_box{(around.lo - Vec3::Constant(3.0 * edge)).cwiseMax(box.lo),
                  (around.hi + Vec3::Constant(3.0 * edge)).cwiseMin(box.hi)};
  if (open || lattice_box.size().prod() > kTrimmedShare * box.size().prod()) lattice_box = box;
  Mesh lattice_mesh =
      open ? std::move(*open_lattice) : mesh_operand(*lattice, settings, lattice_box, edge, stats, true);
  const auto join_start = std::chrono::steady_clock::now();
  const double tolerance = kOnCrease * box.diagonal();
  Mesh mesh;
  std::size_t crease_vertices = 0, loops_count = 0;
  AngleRepair repair;
  run_in_task_arena(settings, stats, [&] {
    const std::vector<CreaseLoop> loops =
        trace_crease_loops(lattice_mesh, *lattice, *cutter, edge, tolerance, open ? &box : nullptr);
    loops_count = loops.size();
    for (const CreaseLoop& loop : loops) crease_vertices += loop.points.size();
    const JoinInput in{lattice_mesh, cutter_mesh, lattice, cutter,      loops, crease_vertices,
                       edge,         settings,    box,     lattice_box, open};
    try {
      mesh = join_faces(in, false, repair);
    } catch (const CreaseError&) {
      // Where the box cuts the part and the faces' runs to the box do not close (a crease nearly along
      // a face of the box), both faces' whole rings at the box are joined anew; where the joined part
      // fails its checks (creases closer than an edge: two loops nearly touching where the surfaces are
      // nearly tangent), both faces are joined on meshes of half the edge, cleaned up to the edge.
      repair = AngleRepair{};
      try {
        if (!open) throw;
        mesh = join_faces(in, true, repair);
      } catch (const CreaseError&) {
        if (split && open) throw;  // the caller joins the mesher's cuts next
        repair = AngleRepair{};
        mesh = join_faces(in, false, repair, true);
      }
    }
    return 0;
  });
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
  // min(a, b) = -max(-a, -b): the same surface, outward the other way.
  if (shape.united)
    for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

}  // namespace

std::optional<Mesh> mesh_two_solids(const CutShape& shape, const Settings& settings, MeshStats* stats) {
  // The operands' cuts by the box split to the edge first (the caps and the joins at the box then follow
  // the cut curve where it turns within a cell). Where those faces do not join, or join with a triangle
  // under kSecondJoinAngle, the mesher's cuts as before, with every fallback, and of two meshes the one
  // with the larger smallest angle. A part the box does not cut is meshed once.
  const MeshStats before = stats ? *stats : MeshStats{};
  bool cut_open = false;
  std::optional<Mesh> split;
  try {
    split = two_solids(shape, settings, stats, true, &cut_open);
  } catch (const CreaseError&) {
    if (!cut_open) throw;
  }
  if (!cut_open || (split && smallest_angle(*split) >= kSecondJoinAngle)) return split;
  const MeshStats split_stats = stats ? *stats : MeshStats{};
  if (stats) *stats = before;
  std::optional<Mesh> plain;
  try {
    plain = two_solids(shape, settings, stats, false, &cut_open);
  } catch (const CreaseError&) {
    if (!split) throw;
  }
  if (split && (!plain || smallest_angle(*plain) <= smallest_angle(*split))) {
    if (stats) *stats = split_stats;
    return split;
  }
  return plain;
}

}  // namespace isopatch
