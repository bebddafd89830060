// Surface-bound isotropic remeshing (Botsch & Kobbelt 2004), see include/isopatch/remesh.hpp.
#include <isopatch/error.hpp>
#include <isopatch/remesh.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/stage_timer.hpp"
#include "remesh/block_edits.hpp"
#include "remesh/box_boundary.hpp"
#include "remesh/defect_region.hpp"
#include "remesh/editable_mesh.hpp"
#include "remesh/laplacian_exactness.hpp"
#include "remesh/remesh_checks.hpp"
#include "remesh/remesh_thresholds.hpp"
#include "remesh/size_field.hpp"
#include "remesh/slot_renumbering.hpp"
#include "remesh/triangle_angle.hpp"
#include "remesh/triangle_measures.hpp"
#include "remesh/valence_flips.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include "surface/project_point.hpp"
#include "surface/sampler.hpp"

namespace isopatch {
namespace {

using namespace remesh_thresholds;

class Remesher {
 public:
  Remesher(const Surface& surface, EditableMesh& mesh, const RemeshSettings& settings, double tolerance)
      : f_(surface), mesh_(mesh), settings_(settings), sizes_(surface, settings), tolerance_(tolerance) {}

  RemeshStats run() {
    if (settings_.local_only) return run_local();
    find_sliding_vertices();
    timed("cleanup_sizes", [&] { sizes_.update(mesh_); });
    const std::size_t steps = static_cast<std::size_t>(settings_.iterations) + 2;
    for (int it = 0; it < settings_.iterations; ++it) {
      report(static_cast<std::size_t>(it), steps);
      timed("cleanup_split", [&] { split_long_edges(); });
      timed("cleanup_sizes", [&] { sizes_.update(mesh_); });
      timed("cleanup_collapse", [&] {
        collapse_short_edges();
        // The collapses' dead slots go before the flips and sweeps walk the slots; a large mesh is
        // also renumbered in space order, as the splits appended their vertices far from their rings.
        compact(mesh_.vertex_slots() >= kSpaceOrderSlots);
      });
      timed("cleanup_sizes", [&] { sizes_.update(mesh_); });
      timed("cleanup_flip", [&] { flip_valences(); });
      timed("cleanup_relax", [&] { relax(); });
      timed("cleanup_sizes", [&] { sizes_.update(mesh_); });
    }
    for (int round = 0; round < 3; ++round) {
      if (timed("cleanup_repair", [&] { return repair_small_angles(); }) == 0) break;
      timed("cleanup_sizes", [&] { sizes_.update(mesh_); });
      timed("cleanup_flip", [&] { flip_valences(); });  // the repairs' collapses leave irregular vertices
      timed("cleanup_relax", [&] { relax(); });
    }
    // Chains that may pass one flip costing energy pull apart the 5-7 pairs neutral chains leave.
    if (settings_.valence_search > 0)
      timed("cleanup_valence_search",
            [&] { flip_valences(GlideLimits{.budget = settings_.valence_search, .max_debt = 2}); });
    // Connectivity is final: relaxation alone evens out the vertex spacing around the irregular vertices
    // (each flip, split or collapse of a round undoes part of what the relaxation of the round did).
    timed("cleanup_relax", [&] { relax(settings_.final_relaxation_rounds); });
    // Splits and collapses left dead slots; the connectivity is final, so the vertices are renumbered along
    // a space-filling curve: each sweep reads the mesh in memory order (half the time on a 1M sphere).
    compact(true);
    report(steps - 2, steps);
    if (settings_.curvature_sweeps > 0) {
      const ExactnessMoveRules rules{
          .project = [this](Vec3& p, Vec3& n, double max_step) { return project(p, n, max_step); },
          .triangle_valid = [this](std::uint32_t t, std::uint32_t v, const Vec3& p,
                                   const Vec3& n) { return triangle_ok_with(t, v, p, n); },
          .size = [this](std::uint32_t v) { return sizes_.at(v); },
          .angle_floor = kExactnessAngleFloor,
          .before_sweep = [this] { check_cancel(); }};
      timed("cleanup_curvature", [&] {
        stats_.exactness_moves = improve_laplacian_exactness(mesh_, rules, settings_.curvature_sweeps);
      });
    }
    report(steps - 1, steps);
    timed("cleanup_repair", [&] { repair_until_settled(); });
    if (settings_.sizes.max_error)
      timed("cleanup_error_bound", [&] { stats_.error_bound_violations = enforce_error_bound(); });
    stats_.gradient_evaluations = f_.gradient_count();
    stats_.hessian_evaluations = sizes_.hessian_evaluations();
    return stats_;
  }

  /// The preview's local repair: the topological fixes (short edges, small angles, valences) act only
  /// where a defect is, then relaxation runs over the vertices near the defects alone (work list), so
  /// the cost follows what needs fixing, not the mesh size.
  RemeshStats run_local() {
    find_sliding_vertices();
    timed("cleanup_sizes", [&] { sizes_.update(mesh_); });
    timed("cleanup_collapse", [&] { collapse_short_edges(); });
    timed("cleanup_repair", [&] { repair_until_settled(); });
    timed("cleanup_flip", [&] { flip_valences(GlideLimits{.budget = kLocalGlideBudget}); });
    // The collapses moved and merged vertices: varying sizes are graded again before the work list.
    timed("cleanup_sizes", [&] { sizes_.update(mesh_); });
    std::vector<std::uint32_t> work;
    timed("cleanup_relax", [&] {
      const DefectThresholds thresholds{.cos_small_angle = std::cos(kLocalAngle * std::numbers::pi / 180.0),
                                        .split_factor = kSplitFactor,
                                        .collapse_factor = collapse_factor()};
      work = vertices_near_defects(mesh_, sizes_, thresholds, kLocalRings);
      relax(work, kLocalRelaxationRounds);
    });
    timed("cleanup_repair", [&] { repair_until_settled(); });
    // The relaxation frees flips that its angles refused: one more greedy pass with neutral chains.
    timed("cleanup_flip", [&] { flip_valences(GlideLimits{.budget = kLocalGlideBudget}); });
    timed("cleanup_relax", [&] { relax(work, kLocalRelaxationRounds); });
    timed("cleanup_repair", [&] { repair_until_settled(); });
    // Only a mesh still short of the margin above the floor pays for chains that may borrow.
    if (settings_.valence_search > 0 && valence_six_share(mesh_) < kLocalValenceShare) {
      timed("cleanup_valence_search", [&] {
        flip_valences(GlideLimits{.budget = settings_.valence_search, .passes = 1, .max_debt = 2});
      });
      timed("cleanup_relax", [&] { relax(work, 2); });
      timed("cleanup_repair", [&] { repair_until_settled(); });
    }
    stats_.gradient_evaluations = f_.gradient_count();
    stats_.hessian_evaluations = sizes_.hessian_evaluations();
    return stats_;
  }

 private:
  /// Drops the mesh's dead slots (EditableMesh::compact, or with space_order
  /// EditableMesh::compact_in_space_order) and renumbers the per-vertex data held here.
  void compact(bool space_order = false) {
    const std::vector<std::uint32_t> new_id = space_order ? mesh_.compact_in_space_order() : mesh_.compact();
    sizes_.renumber(new_id);
    // New slots (from splits) were never in these lists: they stay -1.
    renumber_slots(slide_axis_, new_id, -1);
    renumber_slots(slide_plane_, new_id, -1);
  }

  /// Runs `pass`, adding its wall time to stage `name` of the statistics; returns what it returns.
  template <class Pass>
  std::invoke_result_t<Pass> timed(const char* name, Pass pass) {
    const StageTimer timer(&stats_.times, name);
    return pass();
  }

  /// Reports `done` of `total` clean-up steps through settings.progress (stage "cleanup").
  void report(std::size_t done, std::size_t total) const {
    if (settings_.progress) settings_.progress(Progress{done, total, "cleanup"});
  }

  void check_cancel() const {
    if (settings_.cancel && settings_.cancel->load(std::memory_order_relaxed)) throw LimitError("cancelled");
  }

  /// Whether p lies in the box and inside the region's planes (to within plane_margin()).
  bool in_box(const Vec3& p) const {
    for (const CutPlane& plane : planes_)
      if (plane.distance(p) > plane_margin()) return false;
    if (!settings_.box) return true;
    return (p.array() >= settings_.box->lo.array()).all() && (p.array() <= settings_.box->hi.array()).all();
  }
  double plane_margin() const { return kCutPlaneTolerance * settings_.sizes.largest; }

  /// p moved onto f = 0 (steps at most max_step), with its unit normal; false on failure or outside the box.
  bool project(Vec3& p, Vec3& normal, double max_step) const {
    Vec3 gradient;
    if (!project_to_surface(f_, p, tolerance_, max_step, &gradient)) return false;
    if (!in_box(p)) return false;
    normal = gradient.normalized();
    return true;
  }

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
      const std::uint32_t v = mesh_.triangles[t][static_cast<std::size_t>(i)];
      q[i] = v == from ? p : mesh_.positions[v];
      m[i] = v == from ? n : mesh_.normals[v];
    }
    return triangle_ok(q[0], q[1], q[2], m[0], m[1], m[2]);
  }

  bool triangle_ok(const Triangle& t) const {
    return triangle_ok(mesh_.positions[t[0]], mesh_.positions[t[1]], mesh_.positions[t[2]],
                       mesh_.normals[t[0]], mesh_.normals[t[1]], mesh_.normals[t[2]]);
  }

  double length(std::uint32_t a, std::uint32_t b) const {
    return (mesh_.positions[a] - mesh_.positions[b]).norm();
  }

  double collapse_factor() const {
    if (settings_.sizes.max_error) return kErrorCollapseFactor;
    return settings_.local_only ? kLocalCollapseFactor : kCollapseFactor;
  }

  /// Splits a-b at its midpoint moved onto f = 0 into vertex slot m and triangle slots t, t + 1 (from
  /// EditableMesh::add_split_slots) when the four new triangles are valid. Writes only the rings of a
  /// and b and the new slots (far-apart calls may run at once; callers count the splits).
  bool try_split(std::uint32_t a, std::uint32_t b, std::uint32_t m, std::uint32_t t) {
    const auto e = mesh_.interior_edge(a, b);
    if (!e) return false;
    Vec3 p = 0.5 * (mesh_.positions[a] + mesh_.positions[b]);
    Vec3 n;
    if (!project(p, n, length(a, b))) return false;
    const auto& P = mesh_.positions;
    const auto& N = mesh_.normals;
    if (!triangle_ok(P[e->a], p, P[e->c], N[e->a], n, N[e->c]) ||
        !triangle_ok(p, P[e->b], P[e->c], n, N[e->b], N[e->c]) ||
        !triangle_ok(P[e->b], p, P[e->d], N[e->b], n, N[e->d]) ||
        !triangle_ok(p, P[e->a], P[e->d], n, N[e->a], N[e->d]))
      return false;
    mesh_.split(*e, p, n, m, t);
    return true;
  }

  /// Splits the edges longer than kSplitFactor times their size, the longest first within each block
  /// (block_edits.hpp); edge k of the list has its own new slots, so the numbering does not depend on
  /// the order the blocks ran in.
  void split_long_edges() {
    check_cancel();
    KeyedEdges listed = list_keyed_edges(mesh_, [this](std::uint32_t a, std::uint32_t b, double l) {
      return l > kSplitFactor * sizes_.edge(a, b) ? std::optional<double>(-l) : std::nullopt;
    });
    split_listed(edges_by_key(std::move(listed.keyed)), listed.longest);
  }

  /// try_split on the listed edges by blocks (block_edits.hpp; `longest`: the longest edge); the count.
  std::size_t split_listed(const EdgeList& edges, double longest) {
    const auto [first_vertex, first_triangle] = mesh_.add_split_slots(edges.size());
    const std::size_t splits =
        edit_edges_in_blocks(mesh_, edges, longest, [&](std::uint32_t a, std::uint32_t b, std::size_t k) {
          return try_split(a, b, first_vertex + static_cast<std::uint32_t>(k),
                           first_triangle + 2 * static_cast<std::uint32_t>(k));
        });
    stats_.splits += splits;
    return splits;
  }

  /// The axis of the box face along which boundary vertex v may slide, or -1 (box_boundary.hpp).
  int slide_axis(std::uint32_t v) const { return v < slide_axis_.size() ? slide_axis_[v] : -1; }
  /// The region plane along which boundary vertex v may slide, or -1 (box_boundary.hpp).
  int slide_plane(std::uint32_t v) const { return v < slide_plane_.size() ? slide_plane_[v] : -1; }
  void find_sliding_vertices() {
    planes_ = cut_planes(settings_.cut_planes);
    if (settings_.box) slide_axis_ = sliding_axes(mesh_, *settings_.box, planes_, plane_margin());
    slide_plane_ = sliding_planes(mesh_, planes_, settings_.box ? &*settings_.box : nullptr, plane_margin());
  }

  /// Collapses a into b (or b into a when a is locked); `max_length` bounds the new edges (callers count
  /// the collapses: this writes only the rings of a and b, so far-apart calls may run at once). Two locked
  /// vertices: along their boundary edge (try_collapse_boundary). A `repair` may leave a corner of the cut
  /// one triangle (fewest), a routine collapse never.
  bool try_collapse(std::uint32_t a, std::uint32_t b, double max_length, bool repair = false) {
    if (mesh_.locked[a] && mesh_.locked[b]) return try_collapse_boundary(a, b, max_length);
    if (mesh_.locked[a]) std::swap(a, b);
    const auto e = mesh_.interior_edge(a, b);
    if (!e) return false;
    // Link condition: a and b share exactly the neighbours c and d.
    const std::vector<std::uint32_t> na = mesh_.neighbours(a), nb = mesh_.neighbours(b);
    if (sorted_intersection(na, nb).size() != 2) return false;
    const auto least = [&](std::uint32_t v) { return repair ? fewest(v) : 3u; };
    if (mesh_.valence(e->c) <= least(e->c) || mesh_.valence(e->d) <= least(e->d)) return false;
    if (na.size() + nb.size() - 4 > 9) return false;
    Vec3 p = mesh_.positions[b], n = mesh_.normals[b];
    if (!mesh_.locked[b]) {
      p = 0.5 * (mesh_.positions[a] + mesh_.positions[b]);
      if (!project(p, n, length(a, b))) return false;
    }
    for (const auto* list : {&na, &nb})
      for (std::uint32_t x : *list)
        if (x != a && x != b && (mesh_.positions[x] - p).norm() > max_length) return false;
    // Every remaining triangle of a or b gets the merged vertex at (p, n); under the link condition
    // none holds both.
    for (std::uint32_t v : {a, b})
      for (std::uint32_t t : mesh_.incident[v])
        if (t != e->t_ab && t != e->t_ba && !triangle_ok_with(t, v, p, n)) return false;
    mesh_.collapse(*e, p, n);
    return true;
  }

  /// The fewest neighbours v may keep after a flip or collapse takes one: 3, but 2 (one triangle) at a
  /// corner of the cut (on two faces or planes, never moved), whose wedge may be too narrow for two good
  /// triangles. A sliding cut vertex keeps two: with one, its corners would lie on one nearly straight cut.
  unsigned fewest(std::uint32_t v) const {
    return mesh_.locked[v] && slide_axis(v) < 0 && slide_plane(v) < 0 ? 2u : 3u;
  }

  /// Merges a boundary vertex that may slide (a, else b) into its neighbour along their boundary edge, on
  /// the same box face; the neighbour keeps its position, so the cut stays on the box.
  bool try_collapse_boundary(std::uint32_t a, std::uint32_t b, double max_length) {
    // Vertices within rounding of each other (crossings of segments at one lattice point) merge: none moves.
    const bool same = length(a, b) <= 1e-9 * max_length;
    if (slide_axis(a) < 0 && slide_plane(a) < 0) std::swap(a, b);
    const int axis = slide_axis(a), plane = slide_plane(a);
    const auto on_same_cut = [&](std::uint32_t v) {
      return axis >= 0 ? mesh_.positions[v][axis] == mesh_.positions[a][axis]
                       : on_cut_plane(planes_, plane, mesh_.positions[v], plane_margin());
    };
    if (!same && !on_same_cut(b)) return false;
    const auto e = mesh_.boundary_edge(a, b);
    // An ear (a in one triangle) goes with its triangle when all three corners lie on the same cut: the
    // boundary then runs b - c, still along it (the raw mesh leaves such ears where several crossings
    // of lattice segments fall within rounding of one lattice point on a box face).
    if (!e || (mesh_.incident[a].size() < 2 && !on_same_cut(e->c)) || mesh_.valence(e->c) <= 3) return false;
    if (mesh_.common_neighbours(a, b) != std::vector<std::uint32_t>{e->c}) return false;
    const Vec3& p = mesh_.positions[b];
    for (std::uint32_t x : mesh_.neighbours(a))
      if (!same && x != b && (mesh_.positions[x] - p).norm() > max_length) return false;
    for (std::uint32_t t : mesh_.incident[a])
      if (!same && t != e->t && !triangle_ok_with(t, a, p, mesh_.normals[b])) return false;
    mesh_.collapse_boundary(*e);
    return true;
  }

  void collapse_short_edges() {
    check_cancel();
    KeyedEdges listed = list_keyed_edges(mesh_, [this](std::uint32_t a, std::uint32_t b, double l) {
      return l < collapse_factor() * sizes_.edge(a, b) ? std::optional<double>(l) : std::nullopt;
    });
    const double longest = listed.longest;
    const EdgeList edges = edges_by_key(std::move(listed.keyed));
    // Shortest first within each block; a collapse reads and writes only the rings of its edge's ends.
    stats_.collapses +=
        edit_edges_in_blocks(mesh_, edges, longest, [this](std::uint32_t a, std::uint32_t b, std::size_t) {
          if (!mesh_.alive(a) || !mesh_.alive(b) || !mesh_.adjacent(a, b)) return false;
          const double h = sizes_.edge(a, b);
          if (length(a, b) >= collapse_factor() * h) return false;
          return try_collapse(a, b, kSplitFactor * h);
        });
  }

  /// Flips e when its two new triangles are valid and `accept` agrees, given the cosines of the
  /// smallest angles of the old and of the new pair (a larger cosine is a smaller angle; cosines
  /// rather than angles: this is the inner loop of the flips).
  template <class Accept>
  bool try_flip(const EditableMesh::Edge& e, Accept accept) {
    if (mesh_.valence(e.a) <= fewest(e.a) || mesh_.valence(e.b) <= fewest(e.b)) return false;
    if (mesh_.adjacent(e.c, e.d)) return false;
    const Triangle t1{e.a, e.d, e.c}, t2{e.b, e.c, e.d};
    if (!triangle_ok(t1) || !triangle_ok(t2)) return false;
    const double before = std::max(smallest_angle_cosine(mesh_.triangles[e.t_ab]),
                                   smallest_angle_cosine(mesh_.triangles[e.t_ba]));
    const double after = std::max(smallest_angle_cosine(t1), smallest_angle_cosine(t2));
    if (!accept(before, after)) return false;
    mesh_.flip(e);
    return true;
  }

  double smallest_angle_cosine(const Triangle& t) const {
    return isopatch::smallest_angle_cosine(mesh_.positions[t[0]], mesh_.positions[t[1]],
                                           mesh_.positions[t[2]]);
  }

  /// Valence flips (valence_flips.hpp). A flip that lowers the valence energy may not lower the
  /// pair's smallest angle below min(old, 20 degrees) unless it stays above 30; a neutral flip of a
  /// glide chain only has to stay above kGlideAngle, the relaxation that follows evens it out.
  void flip_valences(const GlideLimits& limits = {}) {
    check_cancel();
    stats_.flips += flip_towards_valence_six(
        mesh_,
        [this](const EditableMesh::Edge& e, bool neutral) {
          if (neutral) return try_flip(e, [this](double, double after) { return after <= cos_glide_; });
          return try_flip(e, [this](double before, double after) {
            return after <= std::max(before, cos_repair_) || after < cos_30_;
          });
        },
        limits);
  }

  /// Tangential relaxation towards the area-weighted centroid of the incident triangles, then back onto
  /// f = 0 (Gauss-Seidel order; a move that would fold a triangle or leave the box is skipped).
  void relax(int rounds = 1) {
    std::vector<std::uint32_t> all;
    for (std::uint32_t v = 0; v < mesh_.vertex_slots(); ++v)
      if (mesh_.alive(v)) all.push_back(v);
    relax(all, rounds);
  }

  /// `rounds` of relax_vertex over `vertices`, by classes of non-adjacent vertices (a move reads only
  /// its neighbours), each class in parallel: the same result for any number of threads.
  void relax(const std::vector<std::uint32_t>& vertices, int rounds) {
    const std::vector<std::vector<std::uint32_t>> classes = mesh_.independent_classes(vertices);
    std::atomic<std::size_t> rejected{0};
    for (int round = 0; round < rounds; ++round) {
      check_cancel();
      for (const std::vector<std::uint32_t>& members : classes)
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, members.size(), 256), [&](const auto& range) {
          for (std::size_t i = range.begin(); i != range.end(); ++i)
            if (!relax_vertex(members[i])) rejected.fetch_add(1, std::memory_order_relaxed);
        });
    }
    stats_.rejected_moves += rejected.load();
  }

  /// Moves v towards the area-weighted centroid of its triangles, tangentially, then onto f = 0; a
  /// sliding cut vertex along its box face. Writes only v. False when the move was refused.
  bool relax_vertex(std::uint32_t v) {
    if (!mesh_.alive(v)) return true;
    if (mesh_.locked[v]) return (slide_axis(v) < 0 && slide_plane(v) < 0) || relax_along_box_face(v);
    Vec3 centroid = Vec3::Zero();
    double area = 0.0;
    for (std::uint32_t t : mesh_.incident[v]) {
      const Triangle& tri = mesh_.triangles[t];
      const Vec3& p0 = mesh_.positions[tri[0]];
      const Vec3& p1 = mesh_.positions[tri[1]];
      const Vec3& p2 = mesh_.positions[tri[2]];
      const double a = 0.5 * (p1 - p0).cross(p2 - p0).norm();
      centroid += a * (p0 + p1 + p2) / 3.0;
      area += a;
    }
    if (!(area > 0.0)) return true;
    centroid /= area;
    const Vec3& p = mesh_.positions[v];
    const Vec3& n = mesh_.normals[v];
    Vec3 move = centroid - p;
    move -= n * n.dot(move);
    Vec3 q = p + move;
    Vec3 nq;
    if (!project(q, nq, std::max(move.norm(), sizes_.at(v)))) return false;
    for (std::uint32_t t : mesh_.incident[v])
      if (!triangle_ok_with(t, v, q, nq)) return false;
    mesh_.positions[v] = q;
    mesh_.normals[v] = nq;
    return true;
  }

  /// Moves a boundary vertex that may slide towards the midpoint of its two boundary neighbours, then
  /// onto the curve where f = 0 meets its box face or region plane (it stays on it and off the others).
  bool relax_along_box_face(std::uint32_t v) {
    const std::vector<std::uint32_t> ends = mesh_.boundary_neighbours(v);
    if (ends.size() != 2) return true;
    const int axis = slide_axis(v);
    const Vec3& p = mesh_.positions[v];
    Vec3 q = 0.5 * (mesh_.positions[ends[0]] + mesh_.positions[ends[1]]);
    const double step = std::max((q - p).norm(), sizes_.at(v));
    Vec3 gradient;
    if (axis < 0) {
      const auto k = static_cast<std::size_t>(slide_plane(v));
      const bool moved =
          project_onto_cut_plane(f_, q, planes_, k, tolerance_, plane_margin(), step, &gradient);
      return moved && in_box(q) && !on_box_face(settings_.box, q) && move_boundary_vertex(v, q, gradient);
    }
    q[axis] = p[axis];
    if (!project_to_surface_in_plane(f_, q, axis, tolerance_, step, &gradient) || !in_box(q)) return false;
    for (int k = 0; k < 3; ++k)
      if (k != axis && (q[k] == settings_.box->lo[k] || q[k] == settings_.box->hi[k])) return true;
    return move_boundary_vertex(v, q, gradient);
  }

  bool move_boundary_vertex(std::uint32_t v, const Vec3& q, const Vec3& gradient) {
    const Vec3 n = gradient.normalized();
    for (std::uint32_t t : mesh_.incident[v])
      if (!triangle_ok_with(t, v, q, n)) return false;
    mesh_.positions[v] = q;
    mesh_.normals[v] = n;
    return true;
  }

  /// repair_small_angles, up to three passes: a repair can make a new small angle next to one it already
  /// passed, so it repeats while it changes things.
  void repair_until_settled() {
    for (int pass = 0; pass < 3; ++pass)
      if (repair_small_angles() == 0) break;
  }

  /// Removes triangles whose smallest angle is below kRepairAngle: flip the longest edge when that
  /// raises the smallest angle of the pair, else collapse the shortest edge. Returns the changes made.
  std::size_t repair_small_angles() {
    check_cancel();
    std::size_t changes = 0;
    for (std::uint32_t t = 0; t < mesh_.triangles.size(); ++t) {
      if (!mesh_.triangle_alive[t]) continue;
      const Triangle tri = mesh_.triangles[t];
      if (smallest_angle_cosine(tri) <= cos_repair_) continue;
      int longest = 0, shortest = 0;
      double lmax = -1.0, lmin = INFINITY;
      for (int i = 0; i < 3; ++i) {
        const double l = length(tri[static_cast<std::size_t>(i)], tri[static_cast<std::size_t>((i + 1) % 3)]);
        if (l > lmax) lmax = l, longest = i;
        if (l < lmin) lmin = l, shortest = i;
      }
      const std::uint32_t a = tri[static_cast<std::size_t>(longest)];
      const std::uint32_t b = tri[static_cast<std::size_t>((longest + 1) % 3)];
      if (const auto e = mesh_.interior_edge(a, b);
          e && try_flip(*e, [](double before, double after) { return after < before; })) {
        ++changes;
        continue;
      }
      // Else collapse the shortest edge, or the next when the link, a fold or a fixed vertex refuses it.
      const int middle = 3 - longest - shortest;
      for (int i : {shortest, middle}) {
        const std::uint32_t c = tri[static_cast<std::size_t>(i)];
        const std::uint32_t d = tri[static_cast<std::size_t>((i + 1) % 3)];
        if (try_collapse(c, d, 2.0 * sizes_.edge(c, d), true)) {
          ++changes;
          ++stats_.collapses;
          break;
        }
      }
    }
    stats_.repairs += changes;
    return changes;
  }

  /// The size law takes the curvature of one point and the edges' spread from the grading, so where the
  /// curvature changes within an edge (the rounded edges of x^16 + y^16 + z^16 = 1) a triangle's centroid
  /// can end up beyond the bound. Splits the longest edge of each triangle beyond kBoundMargin * EPS
  /// (longest first), the new vertex projected onto f = 0, until none is left or kBoundRounds rounds
  /// pass; the small-angle repair follows each round (relaxation would bend the new vertices back:
  /// x^16 + y^16 + z^16 = 1 at EPS 0.0012 stayed at 1.09 EPS with it, 0.89 EPS without). Each round
  /// evaluates f once per triangle. Returns the triangles beyond EPS after the last change: where the
  /// partition cut a thin tip short, the splits there make triangles whose normals leave their vertices'
  /// and are refused (a needle 1:0.05:0.05 along the diagonal).
  std::size_t enforce_error_bound() {
    const double eps = *settings_.sizes.max_error;
    for (int round = 0;; ++round) {
      check_cancel();
      std::size_t beyond = 0;
      std::vector<std::pair<double, std::pair<std::uint32_t, std::uint32_t>>> work;
      for (std::uint32_t t = 0; t < mesh_.triangles.size(); ++t) {
        if (!mesh_.triangle_alive[t]) continue;
        const double distance = centroid_distance(f_, mesh_.positions, mesh_.triangles[t]);
        beyond += distance > eps;
        if (!(distance > kBoundMargin * eps)) continue;
        const auto edge = longest_edge(mesh_.positions, mesh_.triangles[t]);
        work.push_back({-length(edge.first, edge.second), edge});
      }
      if (work.empty() || round == kBoundRounds) return beyond;
      std::sort(work.begin(), work.end());
      work.erase(std::unique(work.begin(), work.end()), work.end());
      const std::size_t splits = split_listed(edges_by_key(std::move(work)), mesh_.longest_edge());
      if (splits == 0) return beyond;
      sizes_.update(mesh_);
      repair_until_settled();
    }
  }

  const double cos_glide_ = std::cos(kGlideAngle * std::numbers::pi / 180.0);
  const double cos_repair_ = std::cos(kRepairAngle * std::numbers::pi / 180.0);
  const double cos_30_ = std::cos(30.0 * std::numbers::pi / 180.0);
  std::vector<int> slide_axis_;   ///< per vertex slot at the start; empty without a box
  std::vector<int> slide_plane_;  ///< per vertex slot at the start; -1 off the region's planes
  std::vector<CutPlane> planes_;  ///< the region's planes (unit normals), set by find_sliding_vertices
  Sampler f_;
  EditableMesh& mesh_;
  const RemeshSettings& settings_;
  SizeField sizes_;
  double tolerance_;
  RemeshStats stats_;
};

}  // namespace

RemeshStats remesh_on_surface(Mesh& mesh, const Surface& surface, const RemeshSettings& settings) {
  check_remesh_settings(settings);
  if (settings.iterations == 0 || mesh.triangles.empty()) return {};
  mesh.validate();
  const Sampler f(surface);
  std::vector<Vec3> normals(mesh.positions.size(), Vec3::Zero());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3 g = f.value_gradient(mesh.positions[v]).gradient;
    if (g.norm() > 0.0) normals[v] = g.normalized();
  }
  const double tolerance = 1e-13 * std::max(bounding_box(mesh).diagonal(), 1e-300);
  EditableMesh editable(mesh, std::move(normals));
  mesh = Mesh{};  // the editable copy is the mesh now: no second copy held through the clean-up
  Remesher remesher(surface, editable, settings, tolerance);
  RemeshStats stats = remesher.run();
  stats.iterations = settings.iterations;
  stats.gradient_evaluations += f.gradient_count();
  mesh = editable.to_mesh();
  return stats;
}

}  // namespace isopatch
