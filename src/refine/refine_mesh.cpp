// The refinement stage (refine_mesh.hpp).
#include "refine/refine_mesh.hpp"

#include <isopatch/error.hpp>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "refine/angle_repair.hpp"
#include "refine/base_edges.hpp"
#include "refine/batched_newton.hpp"
#include "refine/boundary_planes.hpp"
#include "refine/lattice_layout.hpp"
#include "refine/lattice_relaxation.hpp"
#include "refine/piece_map.hpp"
#include "refine/start_points.hpp"
#include "surface/sampler.hpp"

namespace isopatch::refine {
namespace {

/// Base edges, or base triangles, per task.
constexpr std::size_t kEdgesPerTask = 512;
constexpr std::size_t kTrianglesPerTask = 128;
/// A new point may land at most this share of its base edge (or its base triangle's longest edge) from
/// its start: further, it went to another part of the surface.
constexpr double kMaxMoveShare = 0.5;
/// The role value of a vertex made by the refinement (0-5 are the projection mesher's and the clean-up's).
constexpr float kRefinementRole = 6.0f;
/// Passes of the angle repair at most (angle_repair.hpp); a pass that moves nothing ends it.
constexpr int kRepairRounds = 10;
/// Landing tolerance relative to the base's bounding-box diagonal (the clean-up's own).
constexpr double kRelativeTolerance = 1e-13;

void check_cancel(const RefineParams& p) {
  if (p.cancel && p.cancel->load(std::memory_order_relaxed)) throw LimitError("cancelled", "cancel");
}

void report(const RefineParams& p, std::size_t done, std::size_t total) {
  if (p.progress) p.progress(Progress{done, total, "refine"});
}

Vec3 unit_or_zero(const Vec3& v) {
  const double n = v.norm();
  return n > 0.0 ? Vec3(v / n) : Vec3(Vec3::Zero());
}

/// The normal a triangle of piece `piece` has at its corner v: the stored one, or at a vertex on a curve
/// the pieces meet along (whose stored normal is one piece's) that of the triangle's own piece.
using CornerNormal = std::function<Eigen::Vector3f(std::uint32_t v, std::uint32_t piece)>;

/// The number of triangles of `mesh` that turn away from the surface normals at their corners: from
/// the stored `normals` and from the normals of their own piece (output triangle t lies on piece
/// piece_of(t)). Either agreeing is enough: at an I-patch's curve the stored normal is the sound one
/// (its functions are 0/0 at the corners), at a crease between two faces the piece's.
std::size_t turned_triangles(const Mesh& mesh, const std::vector<Eigen::Vector3f>& normals,
                             const CornerNormal& corner_normal,
                             const std::function<std::uint32_t(std::size_t)>& piece_of) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, mesh.triangles.size(), 4096), std::size_t{0},
      [&](const tbb::blocked_range<std::size_t>& r, std::size_t count) {
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          const Triangle& tri = mesh.triangles[t];
          if (faces_the_surface(mesh.positions, normals, tri)) continue;
          const std::uint32_t piece = piece_of(t);
          if (!faces_the_surface(
                  mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]],
                  {corner_normal(tri[0], piece), corner_normal(tri[1], piece), corner_normal(tri[2], piece)}))
            ++count;
        }
        return count;
      },
      std::plus<>());
}

/// The vertices of the triangles under `angle` degrees and of every triangle touching one of them.
std::vector<std::uint8_t> near_small_angles(const Mesh& mesh, double angle) {
  std::vector<std::uint8_t> seed(mesh.vertex_count(), 0), marked(mesh.vertex_count(), 0);
  for (const Triangle& t : mesh.triangles)
    if (smallest_angle_degrees(mesh, t) < angle)
      for (std::uint32_t v : t) seed[v] = 1;
  for (const Triangle& t : mesh.triangles)
    if (seed[t[0]] || seed[t[1]] || seed[t[2]])
      for (std::uint32_t v : t) marked[v] = 1;
  return marked;
}

/// \throw InputError unless `pieces` names at least one function, none null, and one piece below their
///        count per base triangle and per base vertex (or none).
void check_pieces(const Mesh& base, const RefinePieces& pieces) {
  if (pieces.functions.empty()) throw InputError("refine: no function to refine on");
  for (const Surface* s : pieces.functions)
    if (!s) throw InputError("refine: a piece has no function");
  // Each list is empty or names one piece below the functions' count per base vertex (triangle).
  const auto check = [&](const std::vector<std::uint32_t>& list, std::size_t count, const char* what,
                         const char* whats) {
    if (list.empty()) return;
    if (list.size() != count)
      throw InputError("refine: " + std::to_string(list.size()) + " " + what + " pieces for " +
                       std::to_string(count) + " base " + whats);
    for (const std::uint32_t p : list)
      if (p >= pieces.functions.size())
        throw InputError("refine: a base " + std::string(what) + " names piece " + std::to_string(p) +
                         " of " + std::to_string(pieces.functions.size()));
  };
  check(pieces.vertex_piece, base.vertex_count(), "vertex", "vertices");
  check(pieces.triangle_piece, base.triangle_count(), "triangle", "triangles");
}

}  // namespace

RefineResult refine_mesh(const Mesh& base, const Surface& surface, const RefineParams& params) {
  RefinePieces one;
  one.functions = {&surface};
  return refine_pieces(base, one, params);
}

RefineResult refine_pieces(const Mesh& base, const RefinePieces& pieces, const RefineParams& params) {
  if (params.level < 1 || params.level > kMaxLevel)
    throw SettingError("refine", "the refinement level must be 1.." + std::to_string(kMaxLevel));
  check_pieces(base, pieces);
  const BaseEdges edges = base_edges(base);
  const LatticeLayout layout(base, edges, params.level);
  if (params.max_vertices > 0 && layout.vertex_count() > params.max_vertices)
    throw LimitError("the refined mesh would have " + std::to_string(layout.vertex_count()) +
                         " vertices, more than the vertex budget of " + std::to_string(params.max_vertices),
                     "max_vertices");
  const int k = params.level;
  const bool several = pieces.functions.size() > 1;
  const bool with_pieces =
      several || !pieces.triangle_piece.empty() || static_cast<bool>(pieces.curve_points);
  const PieceMap map = map_pieces(base, edges, pieces, k);
  std::vector<std::unique_ptr<Sampler>> samplers;
  std::vector<const Sampler*> functions;
  for (const Surface* s : pieces.functions) {
    samplers.push_back(std::make_unique<Sampler>(*s));
    functions.push_back(samplers.back().get());
  }
  const auto triangle_piece = [&](std::size_t t) {
    return pieces.triangle_piece.empty() ? 0u : pieces.triangle_piece[t];
  };
  const double scale = params.scale > 0.0 ? params.scale : std::max(bounding_box(base).diagonal(), 1e-300);
  const double tolerance = kRelativeTolerance * scale;
  const NewtonLimits limits{tolerance, 12, 0.5};
  const BoundaryPlanes planes(params.box, params.region, 1e-9 * scale);
  const std::size_t total_work = layout.vertex_count() * static_cast<std::size_t>(1 + params.sweeps);
  report(params, 0, total_work);

  RefineResult result;
  Mesh& mesh = result.mesh;
  mesh.positions.resize(layout.vertex_count());
  std::vector<Eigen::Vector3f> normals(layout.vertex_count());
  std::vector<Motion> motion(layout.vertex_count(), Motion::Free);
  // Per output vertex, the function it lies on (only with several pieces).
  std::vector<std::uint32_t> vertex_function;
  if (several) {
    vertex_function.resize(layout.vertex_count());
    std::copy(map.vertex_piece.begin(), map.vertex_piece.end(), vertex_function.begin());
    for (std::uint32_t e = 0; e < edges.size(); ++e)
      for (int j = 1; j < k; ++j) vertex_function[layout.edge_point(e, j)] = map.edge_piece[e];
    for (std::size_t t = 0; t < base.triangle_count(); ++t)
      std::fill_n(vertex_function.begin() + static_cast<std::ptrdiff_t>(layout.inner_start(t)),
                  layout.inner_per_triangle(), triangle_piece(t));
  }

  // Base vertices: their unit normals (a batch per function) and whether the cut or a curve holds them.
  std::vector<Vec3> base_normal(base.vertex_count());
  {
    std::vector<ValueGradient> vg(base.vertex_count());
    value_gradients(functions, base.positions, several ? map.vertex_piece : std::vector<std::uint32_t>{}, vg);
    for (std::size_t v = 0; v < base.vertex_count(); ++v) {
      base_normal[v] = unit_or_zero(vg[v].gradient);
      mesh.positions[v] = base.positions[v];
      normals[v] = base_normal[v].cast<float>();
      if (map.on_curve[v]) motion[v] = Motion::Locked;
    }
  }
  std::vector<int> edge_plane(edges.size(), -1);
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    if (map.on_curve_edge(e))
      for (int j = 1; j < k; ++j) motion[layout.edge_point(e, j)] = Motion::Locked;
    if (!edges.boundary(e) || map.on_curve_edge(e)) continue;
    const auto [a, b] = edges.ends[e];
    motion[a] = motion[b] = Motion::Locked;
    const bool seam = params.seam && params.seam(a, b);
    if (!seam || params.seams_on_planes) edge_plane[e] = planes.common(base.positions[a], base.positions[b]);
    const Motion points = edge_plane[e] >= 0 && !seam ? Motion::Slides : Motion::Locked;
    for (int j = 1; j < k; ++j) motion[layout.edge_point(e, j)] = points;
  }

  // Points on base edges (a curve's own points, or landed), then inside base triangles; each lands on
  // its own (batched_newton.hpp).
  tbb::combinable<std::size_t> failures([] { return std::size_t{0}; });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, k > 1 ? edges.size() : 0, kEdgesPerTask),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      check_cancel(params);
                      std::vector<NewtonPoint> points;
                      points.reserve(r.size() * static_cast<std::size_t>(k - 1));
                      for (std::size_t e = r.begin(); e != r.end(); ++e) {
                        const auto [a, b] = edges.ends[e];
                        const Vec3 &pa = base.positions[a], &pb = base.positions[b];
                        const double length = (pb - pa).norm();
                        for (int j = 1; j < k; ++j) {
                          const double s = static_cast<double>(j) / k;
                          NewtonPoint p;
                          p.position = map.on_curve_edge(static_cast<std::uint32_t>(e))
                                           ? map.curve_points[static_cast<std::size_t>(map.curve_first[e]) +
                                                              static_cast<std::size_t>(j - 1)]
                                           : phong_edge_point(pa, base_normal[a], pb, base_normal[b], s);
                          p.expected_normal = unit_or_zero((1.0 - s) * base_normal[a] + s * base_normal[b]);
                          p.max_move = kMaxMoveShare * length;
                          p.plane = edge_plane[e];
                          p.piece = map.edge_piece[e];
                          points.push_back(p);
                        }
                      }
                      land_on_surface(functions, planes, points, limits);
                      std::size_t i = 0;
                      for (std::size_t e = r.begin(); e != r.end(); ++e) {
                        const bool curve = map.on_curve_edge(static_cast<std::uint32_t>(e));
                        if (map.joins_pieces[e]) ++failures.local();
                        for (int j = 1; j < k; ++j, ++i) {
                          const std::uint32_t v = layout.edge_point(static_cast<std::uint32_t>(e), j);
                          normals[v] = points[i].normal.cast<float>();
                          if (curve) {
                            // The curve's own point, where it is (its landing only gives the normal there):
                            // the curve lies on both pieces' functions to rounding.
                            mesh.positions[v] =
                                map.curve_points[static_cast<std::size_t>(map.curve_first[e]) +
                                                 static_cast<std::size_t>(j - 1)];
                          } else {
                            mesh.positions[v] = points[i].position;
                            if (points[i].landing != Landing::Ok) ++failures.local();
                          }
                        }
                      }
                    });
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, layout.inner_per_triangle() > 0 ? base.triangle_count() : 0,
                                      kTrianglesPerTask),
      [&](const tbb::blocked_range<std::size_t>& r) {
        check_cancel(params);
        std::vector<NewtonPoint> points;
        points.reserve(r.size() * layout.inner_per_triangle());
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          const Triangle& tri = base.triangles[t];
          const Vec3 corner[3] = {base.positions[tri[0]], base.positions[tri[1]], base.positions[tri[2]]};
          const Vec3 normal[3] = {base_normal[tri[0]], base_normal[tri[1]], base_normal[tri[2]]};
          const double longest = std::max({(corner[1] - corner[0]).norm(), (corner[2] - corner[1]).norm(),
                                           (corner[0] - corner[2]).norm()});
          for (int j = 1; j + 1 < k; ++j)
            for (int i = 1; i + j < k; ++i) {
              const double w[3] = {static_cast<double>(k - i - j) / k, static_cast<double>(i) / k,
                                   static_cast<double>(j) / k};
              NewtonPoint p;
              p.position = phong_point(corner, normal, w);
              p.expected_normal = unit_or_zero(w[0] * normal[0] + w[1] * normal[1] + w[2] * normal[2]);
              p.max_move = kMaxMoveShare * longest;
              p.piece = triangle_piece(t);
              points.push_back(p);
            }
        }
        land_on_surface(functions, planes, points, limits);
        std::size_t i = 0;
        for (std::size_t t = r.begin(); t != r.end(); ++t)
          for (std::size_t m = 0; m < layout.inner_per_triangle(); ++m, ++i) {
            const std::size_t v = layout.inner_start(t) + m;
            mesh.positions[v] = points[i].position;
            normals[v] = points[i].normal.cast<float>();
            if (points[i].landing != Landing::Ok) ++failures.local();
          }
      });
  result.failed_points = failures.combine(std::plus<>());
  if (k == 1) result.failed_points += map.joining_edges;
  mesh.triangles.resize(layout.triangle_count());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, base.triangle_count(), kTrianglesPerTask),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t t = r.begin(); t != r.end(); ++t)
                        layout.emit_triangles(t, mesh.triangles.data() + t * static_cast<std::size_t>(k * k));
                    });
  const auto evaluations = [&] {
    std::uint64_t n = 0;
    for (const auto& s : samplers) n += s->gradient_count();
    return n;
  };
  if (result.failed_points == 0) {
    // A vertex on a curve where pieces meet at an angle (a crease) has its stored normal from one piece:
    // the triangles of the other piece are checked against their own function's normal there.
    std::vector<std::uint8_t> on_curve(several ? mesh.vertex_count() : 0, 0);
    if (several) {
      for (std::size_t v = 0; v < base.vertex_count(); ++v) on_curve[v] = map.on_curve[v];
      for (std::uint32_t e = 0; e < edges.size(); ++e)
        if (map.on_curve_edge(e))
          for (int j = 1; j < k; ++j) on_curve[layout.edge_point(e, j)] = 1;
    }
    // (Where the piece's gradient vanishes or is not finite, as at an I-patch's corner, the stored one.)
    const CornerNormal corner_normal = [&](std::uint32_t v, std::uint32_t piece) {
      if (!several || !on_curve[v] || vertex_function[v] == piece) return normals[v];
      const Vec3 g = functions[piece]->value_gradient_unchecked(mesh.positions[v]).gradient;
      const double length = g.norm();
      return std::isfinite(length) && length > 0.0 ? Eigen::Vector3f((g / length).cast<float>()) : normals[v];
    };
    const auto kk = static_cast<std::size_t>(k * k);
    result.failed_points =
        turned_triangles(mesh, normals, corner_normal, [&](std::size_t t) { return triangle_piece(t / kk); });
  }
  if (result.failed_points > 0) {
    result.gradient_evaluations = evaluations();
    result.mesh = Mesh{};
    return result;
  }
  report(params, layout.vertex_count(), total_work);

  LatticeRelaxation relaxation(mesh, normals, motion, layout, edges, edge_plane, functions, vertex_function,
                               planes, limits, params.sweep_block);
  if (params.guard_angles) relaxation.set_angle_guard(params.angle_target);
  for (int s = 0; s < params.sweeps; ++s) {
    check_cancel(params);
    result.rejected_moves += relaxation.sweep();
    report(params, layout.vertex_count() * static_cast<std::size_t>(2 + s), total_work);
  }
  if (params.angle_sweeps > 0) {
    const std::vector<std::uint8_t> near = near_small_angles(mesh, params.angle_target);
    result.angle_vertices = static_cast<std::size_t>(std::count(near.begin(), near.end(), std::uint8_t{1}));
    for (int s = 0; s < params.angle_sweeps && result.angle_vertices > 0; ++s) {
      check_cancel(params);
      result.rejected_moves += relaxation.sweep(&near);
    }
  }
  result.smallest_angle = smallest_angle_degrees(mesh);
  if (params.repair_angle > 0.0 && result.smallest_angle < params.repair_angle)
    result.repaired_vertices = repair_small_angles(
        mesh, normals, AngleRepairInput{motion, functions, vertex_function, planes, limits},
        params.repair_angle, kRepairRounds);
  if (result.repaired_vertices > 0) result.smallest_angle = smallest_angle_degrees(mesh);
  if (const std::vector<float>* role = base.find_attribute("role")) {
    std::vector<float> roles(mesh.vertex_count(), kRefinementRole);
    std::copy(role->begin(), role->end(), roles.begin());
    mesh.set_attribute("role", std::move(roles));
  }
  if (with_pieces) {
    result.triangle_piece.resize(mesh.triangle_count());
    for (std::size_t t = 0; t < base.triangle_count(); ++t)
      std::fill_n(
          result.triangle_piece.begin() + static_cast<std::ptrdiff_t>(t * static_cast<std::size_t>(k * k)),
          k * k, triangle_piece(t));
    result.vertex_piece.resize(mesh.vertex_count());
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
      result.vertex_piece[v] = static_cast<std::int32_t>(vertex_function.empty() ? 0 : vertex_function[v]);
    for (std::size_t v = 0; v < base.vertex_count(); ++v)
      if (map.on_curve[v]) result.vertex_piece[v] = -1;
    for (std::uint32_t e = 0; e < edges.size(); ++e)
      if (map.on_curve_edge(e))
        for (int j = 1; j < k; ++j) result.vertex_piece[layout.edge_point(e, j)] = -1;
  }
  result.gradient_evaluations = evaluations();
  return result;
}

}  // namespace isopatch::refine
